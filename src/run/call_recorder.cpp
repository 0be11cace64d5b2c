// The recording half of record and replay (call_trace.hpp): a NodeContext and a Comm that pass
// every call on to the backend's and append it to the node's calls.
#include "run/call_trace.hpp"

namespace zc {

namespace {

// One node's recording. The node actors of a simulation take turns on one thread, so they may
// share the trace's tables.
class RankRecorder {
public:
  RankRecorder(CallTrace& t, NodeContext& inner) : trace_(t), inner_(inner) {
    const auto r = std::size_t(inner.rank());
    if (trace_.ranks.size() <= r) trace_.ranks.resize(r + 1);
    trace_.nodes = inner.nodes();
    trace_.topology = inner.comm().topology();
  }
  NodeContext& inner() { return inner_; }
  CallTrace& trace() { return trace_; }
  Call& push(CallKind k) {
    flush_metrics();
    auto& calls = trace_.ranks[std::size_t(inner_.rank())];
    calls.push_back({});
    calls.back().kind = k;
    return calls.back();
  }
  std::uint32_t next_handle() { return handles_++; }
  // The metrics are written through a reference: they are compared with the last state recorded
  // at the node's next call after metrics() and at its end.
  void touch_metrics() { metrics_touched_ = true; }
  void flush_metrics() {
    if (!metrics_touched_) return;
    metrics_touched_ = false;
    std::string now = inner_.metrics().dump();
    if (now == last_metrics_) return;
    last_metrics_ = now;
    trace_.metrics.push_back(std::move(now));
    push(CallKind::Metrics).index = std::uint32_t(trace_.metrics.size() - 1);
  }

private:
  CallTrace& trace_;
  NodeContext& inner_;
  std::uint32_t handles_ = 0;
  bool metrics_touched_ = false;
  std::string last_metrics_ = "{}";
};

class RecordedSend final : public SendRequest {
public:
  RecordedSend(RankRecorder& rec, SendHandle inner, std::uint32_t id)
      : rec_(rec), inner_(std::move(inner)), id_(id) {}
  void wait() override {
    rec_.push(CallKind::Wait).handle = id_;
    inner_->wait();
  }
  ~RecordedSend() override { rec_.push(CallKind::Drop).handle = id_; }

private:
  RankRecorder& rec_;
  SendHandle inner_;
  std::uint32_t id_;
};

std::uint32_t add_blocks(CallTrace& t, const Blocks& blocks) {
  std::vector<TracedBlock> b;
  for (const Block& x : blocks)
    b.push_back({x.owner, x.data.payload.size(), x.data.charged});
  t.blocks.push_back(std::move(b));
  return std::uint32_t(t.blocks.size() - 1);
}

class RecordingComm final : public Comm {
public:
  RecordingComm(RankRecorder& rec, Comm& inner) : rec_(rec), inner_(inner) {}
  int rank() const override { return inner_.rank(); }
  int size() const override { return inner_.size(); }
  Topology topology() const override { return inner_.topology(); }
  using Comm::isend;
  using Comm::send;
  SendHandle isend(int dst, int tag, Message m) override {
    Call& c = message_call(CallKind::Isend, dst, tag, m);
    const std::uint32_t id = c.handle = rec_.next_handle();
    return std::make_unique<RecordedSend>(rec_, inner_.isend(dst, tag, std::move(m)), id);
  }
  void send(int dst, int tag, Message m) override {
    message_call(CallKind::Send, dst, tag, m);
    inner_.send(dst, tag, std::move(m));
  }
  SendHandle isend_blocks(int dst, int tag, Blocks blocks) override {
    Call& c = blocks_call(CallKind::IsendBlocks, dst, tag, blocks);
    const std::uint32_t id = c.handle = rec_.next_handle();
    return std::make_unique<RecordedSend>(rec_, inner_.isend_blocks(dst, tag, std::move(blocks)),
                                          id);
  }
  void send_blocks(int dst, int tag, Blocks blocks) override {
    blocks_call(CallKind::SendBlocks, dst, tag, blocks);
    inner_.send_blocks(dst, tag, std::move(blocks));
  }
  Message recv_message(int src, int tag, int* from) override {
    int got = 0;
    Message m = inner_.recv_message(src, tag, &got);
    recv_call(src, tag, got, from);
    return m;
  }
  Blocks recv_blocks(int src, int tag, int* from) override {
    int got = 0;
    Blocks b = inner_.recv_blocks(src, tag, &got);
    recv_call(src, tag, got, from);
    return b;
  }
  double now() const override {
    rec_.trace().read_clock = true;
    return inner_.now();
  }

private:
  Call& message_call(CallKind k, int dst, int tag, const Message& m) {
    Call& c = rec_.push(k);
    c.peer = dst;
    c.tag = tag;
    c.size = m.payload.size();
    c.charged = m.charged;
    return c;
  }
  Call& blocks_call(CallKind k, int dst, int tag, const Blocks& blocks) {
    const std::uint32_t index = add_blocks(rec_.trace(), blocks);
    Call& c = rec_.push(k);
    c.peer = dst;
    c.tag = tag;
    c.index = index;
    return c;
  }
  void recv_call(int src, int tag, int got, int* from) {
    Call& c = rec_.push(CallKind::Recv);
    c.peer = src;
    c.tag = tag;
    c.from = got;
    if (from) *from = got;
  }

  RankRecorder& rec_;
  Comm& inner_;
};

class RecordingNode final : public NodeContext {
public:
  explicit RecordingNode(RankRecorder& rec) : rec_(rec), in_(rec.inner()), comm_(rec, in_.comm()) {}
  Comm& comm() override { return comm_; }
  const Scene& scene() const override { return in_.scene(); }
  const SceneFacts& scene_facts() const override { return in_.scene_facts(); }
  const AlgorithmOptions& options() const override { return in_.options(); }
  void charge(const Counters& work) override {
    CallTrace& t = rec_.trace();
    t.counters.push_back(work);
    rec_.push(CallKind::Charge).index = std::uint32_t(t.counters.size() - 1);
    in_.charge(work);
  }
  void phase_begin(const std::string& name) override {
    const std::uint32_t id = rec_.trace().string_id(name);
    rec_.push(CallKind::PhaseBegin).index = id;
    in_.phase_begin(name);
  }
  void phase_end() override {
    rec_.push(CallKind::PhaseEnd);
    in_.phase_end();
  }
  void start_timed_region() override {
    rec_.push(CallKind::TimedStart);
    in_.start_timed_region();
  }
  void end_timed_region() override {
    rec_.push(CallKind::TimedEnd);
    in_.end_timed_region();
  }
  void alloc(double bytes, const std::string& what) override {
    const std::uint32_t id = rec_.trace().string_id(what);
    Call& c = rec_.push(CallKind::Alloc);
    c.bytes = bytes;
    c.index = id;
    in_.alloc(bytes, what);
  }
  void release(double bytes) override {
    rec_.push(CallKind::Release).bytes = bytes;
    in_.release(bytes);
  }
  // The pictures are not recorded: a replay takes the recorded run's image section.
  void deliver_image(int frame, Framebuffer image) override {
    in_.deliver_image(frame, std::move(image));
  }
  void deliver_rows(int frame, Framebuffer rows) override {
    in_.deliver_rows(frame, std::move(rows));
  }
  nlohmann::json& metrics() override {
    rec_.touch_metrics();
    return in_.metrics();
  }

private:
  RankRecorder& rec_;
  NodeContext& in_;
  RecordingComm comm_;
};

std::function<void(NodeContext&)> recorded(std::function<void(NodeContext&)> program,
                                           std::shared_ptr<CallTrace> trace) {
  return [program = std::move(program), trace = std::move(trace)](NodeContext& ctx) {
    RankRecorder rec(*trace, ctx);
    RecordingNode node(rec);
    program(node);
    rec.touch_metrics();
    rec.flush_metrics();
  };
}

} // namespace

Algorithm recording_algorithm(const Algorithm& a, std::shared_ptr<CallTrace> trace) {
  Algorithm r = a;
  r.node = recorded(a.node, trace);
  if (a.host) r.host = recorded(a.host, trace);
  return r;
}

} // namespace zc
