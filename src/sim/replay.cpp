#include "sim/replay.hpp"

#include <exception>
#include <stdexcept>

#include "sim/sim_comm.hpp"
#include "sim/simulation.hpp"

namespace zc {

namespace {

// Why this process's replay was abandoned ("" while it holds).
std::string& divergence() {
  static std::string why;
  return why;
}

[[noreturn]] void diverge(int rank, const std::string& why) {
  if (divergence().empty()) divergence() = "node " + std::to_string(rank) + ": " + why;
  throw std::runtime_error("replay diverged: " + why);
}

// A recorded send again: counted and charged as the recorded message, with no bytes (nobody reads
// a replay's messages).
SendHandle resend(SimComm& comm, const Call& c) {
  return comm.isend_unread(c.peer, c.tag, std::size_t(c.size), std::size_t(c.charged), false);
}

// A recorded bundle of blocks again, counted and charged as the blocks' packed form.
SendHandle resend_blocks(SimComm& comm, const Call& c, const std::vector<TracedBlock>& blocks) {
  std::size_t bytes = 0, charged = 0;
  for (const TracedBlock& b : blocks) {
    bytes += std::size_t(b.size);
    charged += std::size_t(b.charged);
  }
  return comm.isend_unread(c.peer, c.tag, packed_blocks_size(blocks.size(), bytes),
                           blocks_charged(blocks.size(), charged), true);
}

// The phases a node program opened close when it unwinds (NodeContext::Phase, which every
// algorithm uses), out of memory or killed at the end of a failed run: so do the replayed ones.
class OpenPhases {
public:
  explicit OpenPhases(NodeContext& ctx) : ctx_(ctx) {}
  ~OpenPhases() {
    if (std::uncaught_exceptions() == 0) return;
    for (; open_ > 0; --open_)
      ctx_.phase_end();
  }
  OpenPhases(const OpenPhases&) = delete;
  OpenPhases& operator=(const OpenPhases&) = delete;
  void begin(const std::string& name) {
    ctx_.phase_begin(name);
    ++open_;
  }
  void end() {
    ctx_.phase_end();
    if (open_ > 0) --open_;
  }

private:
  NodeContext& ctx_;
  int open_ = 0;
};

// The sends in flight of one node, by the recorded handle number.
class Sends {
public:
  Sends() = default;
  Sends(const Sends&) = delete;
  Sends& operator=(const Sends&) = delete;
  // A node killed at the end of a failed run (or abandoning its replay) drops its sends without
  // waiting: the run is over and its clock stopped (a killed program's handles could not wait
  // either), and the node that failed of its own unwinds with none in flight (replay_alloc).
  ~Sends() {
    if (std::uncaught_exceptions() == 0) return;
    for (auto& h : handles_)
      static_cast<void>(h.release());
  }
  void add(std::uint32_t id, SendHandle h) {
    if (handles_.size() <= id) handles_.resize(id + 1);
    handles_[id] = std::move(h);
  }
  void wait(std::uint32_t id) {
    if (id < handles_.size() && handles_[id]) handles_[id]->wait();
    if (id < handles_.size()) handles_[id] = nullptr; // a waited send's handle does nothing more
  }
  void drop(std::uint32_t id) {
    if (id < handles_.size()) handles_[id] = nullptr;
  }
  bool in_flight() const {
    for (const auto& h : handles_)
      if (h) return true;
    return false;
  }

private:
  std::vector<SendHandle> handles_;
};

void replay_alloc(NodeContext& ctx, const Call& c, const CallTrace& t, const Sends& sends) {
  try {
    ctx.alloc(c.bytes, t.strings.at(c.index));
  } catch (const OutOfNodeMemory&) {
    // The program unwinds from here: its sends' handles wait for their messages as they are
    // destroyed, in an order the trace does not know.
    if (sends.in_flight()) diverge(ctx.rank(), "out of memory with sends in flight");
    throw;
  }
}

void replay_call(NodeContext& ctx, SimComm& comm, const CallTrace& t, const Call& c,
                 OpenPhases& phases, Sends& sends) {
  switch (c.kind) {
  case CallKind::Charge:
    ctx.charge(t.counters.at(c.index));
    break;
  case CallKind::PhaseBegin:
    phases.begin(t.strings.at(c.index));
    break;
  case CallKind::PhaseEnd:
    phases.end();
    break;
  case CallKind::TimedStart:
    ctx.start_timed_region();
    break;
  case CallKind::TimedEnd:
    ctx.end_timed_region();
    break;
  case CallKind::Alloc:
    replay_alloc(ctx, c, t, sends);
    break;
  case CallKind::Release:
    ctx.release(c.bytes);
    break;
  case CallKind::Isend:
    sends.add(c.handle, resend(comm, c));
    break;
  case CallKind::IsendBlocks:
    sends.add(c.handle, resend_blocks(comm, c, t.blocks.at(c.index)));
    break;
  case CallKind::Send:
    resend(comm, c)->wait();
    break;
  case CallKind::SendBlocks:
    resend_blocks(comm, c, t.blocks.at(c.index))->wait();
    break;
  case CallKind::Wait:
    sends.wait(c.handle);
    break;
  case CallKind::Drop:
    sends.drop(c.handle);
    break;
  case CallKind::Recv: {
    int from = 0;
    comm.take(c.peer, c.tag, &from);
    if (from != c.from)
      diverge(ctx.rank(), "a receive from any source with tag " + std::to_string(c.tag) +
                              " got node " + std::to_string(from) + ", recorded node " +
                              std::to_string(c.from));
    break;
  }
  case CallKind::Metrics:
    ctx.metrics() = nlohmann::json::parse(t.metrics.at(c.index));
    break;
  }
}

void replay_rank(const CallTrace& t, NodeContext& ctx) {
  if (ctx.nodes() != t.nodes || ctx.comm().topology() != t.topology)
    diverge(ctx.rank(), "recorded on another node count or topology");
  auto* comm = dynamic_cast<SimComm*>(&ctx.comm());
  if (!comm) throw std::logic_error("a replay runs on the simulator");
  if (std::size_t(ctx.rank()) >= t.ranks.size()) diverge(ctx.rank(), "not recorded");
  OpenPhases phases(ctx);
  Sends sends; // destroyed before the phases close, as a program's inner scopes are
  for (const Call& c : t.ranks[std::size_t(ctx.rank())])
    replay_call(ctx, *comm, t, c, phases, sends);
}

Algorithm replaying_algorithm(const Algorithm& a, const std::shared_ptr<const CallTrace>& t) {
  Algorithm r = a;
  r.node = [t](NodeContext& ctx) { replay_rank(*t, ctx); };
  if (a.host) r.host = [t](NodeContext& ctx) { replay_rank(*t, ctx); };
  return r;
}

} // namespace

RunResult record_simulation(const RunConfig& cfg, const Scene* preloaded,
                            std::shared_ptr<CallTrace>& trace, PlatformModel* model) {
  trace = std::make_shared<CallTrace>();
  RunConfig c = cfg;
  c.custom = std::make_shared<const Algorithm>(
      recording_algorithm(cfg.custom ? *cfg.custom : find_algorithm(cfg.algorithm), trace));
  RunResult r = run_simulation(c, preloaded, model);
  if (!r.ok() || trace->read_clock)
    trace = nullptr;
  else
    trace->image = r.report.image;
  return r;
}

std::optional<RunResult> replay_simulation(const RunConfig& cfg, const Scene* preloaded,
                                           std::shared_ptr<const CallTrace> trace, std::string* why,
                                           PlatformModel* model) {
  divergence().clear();
  RunConfig c = cfg;
  c.custom = std::make_shared<const Algorithm>(
      replaying_algorithm(cfg.custom ? *cfg.custom : find_algorithm(cfg.algorithm), trace));
  RunResult r = run_simulation(c, preloaded, model);
  if (!divergence().empty()) {
    if (why) *why = divergence();
    return std::nullopt;
  }
  if (r.ok()) r.report.image = trace->image;
  return r;
}

} // namespace zc
