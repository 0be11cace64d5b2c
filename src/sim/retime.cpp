#include "sim/retime.hpp"

#include <algorithm>
#include <deque>
#include <limits>
#include <map>
#include <queue>
#include <unordered_map>

#include "comm/comm.hpp"
#include "sim/sim_cost.hpp"
#include "sim/sim_network.hpp"

namespace zc {

namespace {

constexpr double kUnknown = std::numeric_limits<double>::infinity();

struct Msg {
  int src = 0, dst = 0, tag = 0;
  double sent_at = 0, arrival = kUnknown;
  std::vector<Hold> holds;
  std::size_t stage = 0, next_channel = 0;
};

// Delivery's channel bookkeeping (sim/delivery.cpp), without SimGrid.
struct Channel {
  const Msg* owner = nullptr;
  double free_at = 0;
  std::deque<Msg*> queue;
  bool release_pending = false;
};

struct Rank {
  std::size_t pc = 0;
  bool done = false;
  enum class Wait { None, Arrival, Recv } wait = Wait::None;
  const Msg* awaited = nullptr;
  int recv_src = 0, recv_tag = 0;
  double deadline = kUnknown; // its pending wake-up
  std::uint64_t generation = 0;
  std::vector<std::pair<std::uint32_t, double>> open; // phase (string id), its start
  std::vector<double> totals;                         // by string id
  std::vector<char> entered;                          // by string id
  std::vector<std::uint32_t> order;                   // phases in the order first entered
  std::vector<Msg*> handles;
  double memory = 0, capacity = 0;
  double timed_start = 0, timed_end = 0, finish = 0;
  bool timed = false, timed_ended = false;
};

struct Event {
  double time;
  int order;         // ranks in rank order, the network after them
  std::uint64_t seq; // then first scheduled first
  int rank;          // -1: a network event
  enum class Net { NextStage, Release } net = Net::Release;
  Msg* m = nullptr;
  std::uint32_t channel = 0;
  std::uint64_t generation = 0;
  bool operator>(const Event& o) const {
    if (time != o.time) return time > o.time;
    if (order != o.order) return order > o.order;
    return seq > o.seq;
  }
};

class Retimer {
public:
  Retimer(const CallTrace& t, const RetimeMachine& m, const ModelDraw& d)
      : t_(t), m_(m), net_params_(apply_draw(m.net, d)),
        net_(net_params_, m.topology, m.nodes, m.fidelity, {}, unused_cost_),
        circuit_(m.fidelity == Fidelity::Circuit), ranks_(t.ranks.size()), inbox_(t.ranks.size()) {
    for (std::size_t r = 0; r < t.ranks.size(); ++r) {
      const CostTable& c = m.cost[std::min(r, m.cost.size() - 1)];
      cost_.push_back(apply_draw(r < std::size_t(m.nodes) ? c : m.cost.front(), d));
      Rank& k = ranks_[r];
      k.totals.assign(t.strings.size(), 0.0);
      k.entered.assign(t.strings.size(), 0);
      if (r < std::size_t(m.nodes) && r < m.memory.size()) {
        k.capacity = m.memory[r];
        k.memory = m.os_resident * d.os_resident;
      }
    }
    for (const auto& s : t.strings)
      phase_factor_.push_back(d.phase(s));
    no_phase_factor_ = d.phase("");
  }

  RetimedRun run() {
    for (std::size_t r = 0; r < ranks_.size(); ++r)
      schedule_rank(int(r), 0.0);
    while ((!events_.empty() || !net_events_.empty()) && result_.status == RetimedRun::Status::Ok) {
      if (!net_events_.empty() && (events_.empty() || events_.top() > net_events_.top())) {
        // The network's actor handles every event due by now before it yields.
        now_ = net_events_.top().time;
        while (!net_events_.empty() && net_events_.top().time <= now_) {
          const Event e = net_events_.top();
          net_events_.pop();
          process(e);
        }
        continue;
      }
      const Event e = events_.top();
      events_.pop();
      now_ = e.time;
      if (e.generation == ranks_[std::size_t(e.rank)].generation) resume(e.rank);
    }
    if (result_.status == RetimedRun::Status::Ok) finish();
    return result_;
  }

private:
  // A wake-up as Wakeups dates it: a wait of `seconds` from now, at least the precision.
  double after(double seconds) const {
    return seconds > 0 ? now_ + std::max(seconds, m_.precision) : now_;
  }
  void schedule_rank(int r, double time) {
    Rank& k = ranks_[std::size_t(r)];
    k.deadline = time;
    events_.push({time, r, seq_++, r, Event::Net::Release, nullptr, 0, ++k.generation});
  }
  void schedule_net(double time, Event::Net kind, Msg* m, std::uint32_t channel) {
    net_events_.push({time, int(ranks_.size()) + 1, seq_++, -1, kind, m, channel, 0});
  }

  void diverge(RetimedRun::Status s, const std::string& why) {
    result_.status = s;
    result_.why = why;
  }

  void resume(int r);
  bool step(int r, Rank& k, const Call& c);
  bool await(int r, Rank& k, const Msg* m);
  bool receive(int r, Rank& k, const Call& c);
  Msg* post(int r, const Call& c);
  void arrived(Msg& m);
  void charge(Rank& k, const Counters& w, int r);

  // Circuit fidelity.
  std::uint32_t channel_id(std::pair<int, int> c);
  void advance(Msg* m, double t);
  bool end_hold(Msg* m, double end);
  void schedule_release(std::uint32_t id);
  void hand_over(std::uint32_t id, std::vector<Msg*>& woken);
  void process(const Event& e);

  void finish();

  const CallTrace& t_;
  const RetimeMachine& m_;
  NetworkParams net_params_;
  SimCost unused_cost_; // the simulator's own event counts: none here
  SimNetwork net_;
  bool circuit_;
  std::vector<CostTable> cost_;
  std::vector<double> phase_factor_;
  double no_phase_factor_ = 1;
  std::vector<Rank> ranks_;
  std::vector<std::vector<Msg*>> inbox_; // by destination, pending in send order
  std::vector<char> seen_;               // receive()'s scratch: sources met
  std::deque<Msg> msgs_;
  std::unordered_map<std::uint64_t, std::uint32_t> channel_ids_; // (from, to) -> index
  std::vector<Channel> channels_;
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> events_;     // ranks
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> net_events_; // network
  std::uint64_t seq_ = 0;
  double now_ = 0;
  RetimedRun result_;
};

void Retimer::resume(int r) {
  Rank& k = ranks_[std::size_t(r)];
  k.deadline = kUnknown;
  const auto& calls = t_.ranks[std::size_t(r)];
  if (k.wait == Rank::Wait::Arrival && !await(r, k, k.awaited)) return;
  if (k.wait == Rank::Wait::Recv && !receive(r, k, calls[k.pc - 1])) return;
  while (k.pc < calls.size()) {
    const Call& c = calls[k.pc++];
    if (!step(r, k, c) || result_.status != RetimedRun::Status::Ok) return;
  }
  // A handle still open completes before it dies, as the program's would.
  for (Msg*& h : k.handles)
    if (h) {
      if (!await(r, k, h)) return;
      h = nullptr;
    }
  k.done = true;
  k.finish = now_;
}

// Whether the rank goes on at once (false: it waits, and resumes later).
bool Retimer::step(int r, Rank& k, const Call& c) {
  switch (c.kind) {
  case CallKind::Charge:
    charge(k, t_.counters[c.index], r);
    return k.deadline == kUnknown;
  case CallKind::PhaseBegin:
    k.open.emplace_back(c.index, now_);
    if (!k.entered[c.index]) k.order.push_back(c.index);
    k.entered[c.index] = 1;
    return true;
  case CallKind::PhaseEnd:
    if (!k.open.empty()) {
      k.totals[k.open.back().first] += now_ - k.open.back().second;
      k.open.pop_back();
    }
    return true;
  case CallKind::TimedStart:
    k.timed_start = now_;
    k.timed = true;
    return true;
  case CallKind::TimedEnd:
    k.timed_end = now_;
    k.timed_ended = true;
    return true;
  case CallKind::Alloc:
    k.memory += c.bytes;
    if (k.capacity > 0 && k.memory > k.capacity)
      diverge(RetimedRun::Status::OutOfMemory,
              "node " + std::to_string(r) + " out of memory: " + t_.strings[c.index]);
    return true;
  case CallKind::Release:
    k.memory = std::max(0.0, k.memory - c.bytes);
    return true;
  case CallKind::Isend:
  case CallKind::IsendBlocks: {
    if (k.handles.size() <= c.handle) k.handles.resize(c.handle + 1, nullptr);
    if (Msg* old = k.handles[c.handle]) { // the slot's old handle dies first
      k.handles[c.handle] = nullptr;
      --k.pc; // this call again once the old send has arrived
      return await(r, k, old);
    }
    k.handles[c.handle] = post(r, c);
    return true;
  }
  case CallKind::Send:
  case CallKind::SendBlocks:
    return await(r, k, post(r, c));
  case CallKind::Wait:
  case CallKind::Drop: {
    if (c.handle >= k.handles.size() || !k.handles[c.handle]) return true;
    Msg* m = k.handles[c.handle];
    k.handles[c.handle] = nullptr;
    return await(r, k, m);
  }
  case CallKind::Recv:
    return receive(r, k, c);
  case CallKind::Metrics:
    return true;
  }
  return true;
}

void Retimer::charge(Rank& k, const Counters& w, int r) {
  const double f = k.open.empty() ? no_phase_factor_ : phase_factor_[k.open.back().first];
  const double s = cost_[std::size_t(r)].seconds(w) * f;
  if (s > 0) schedule_rank(r, after(s));
}

bool Retimer::await(int r, Rank& k, const Msg* m) {
  if (m->arrival <= now_) {
    k.wait = Rank::Wait::None;
    return true;
  }
  k.wait = Rank::Wait::Arrival;
  k.awaited = m;
  if (m->arrival != kUnknown) schedule_rank(r, after(m->arrival - now_));
  return false;
}

// Inbox::take's rule: from one source its oldest message of the tag; from any source, among the
// sources' oldest ones, the first arrived (the lower source on a tie).
bool Retimer::receive(int r, Rank& k, const Call& c) {
  // The pending messages in send order: a source's first one with the tag is its oldest.
  auto& box = inbox_[std::size_t(r)];
  int got = -1;
  double wake = kUnknown, best = kUnknown;
  std::size_t recorded = box.size(); // the recorded sender's oldest, if pending
  seen_.resize(ranks_.size(), 0);    // all 0 between calls: only the sources met are reset below
  for (std::size_t i = 0; i < box.size(); ++i) {
    const Msg* m = box[i];
    if (m->tag != c.tag || seen_[std::size_t(m->src)]) continue;
    seen_[std::size_t(m->src)] = 1;
    if (m->src == c.from) recorded = i;
    if (c.peer != kAnySource && m->src != c.peer) continue;
    if (m->arrival <= now_ &&
        (got < 0 || m->arrival < best || (m->arrival == best && m->src < got))) {
      got = m->src;
      best = m->arrival;
    }
    wake = std::min(wake, m->arrival);
  }
  for (const Msg* m : box)
    seen_[std::size_t(m->src)] = 0;
  // Under a draw, a receive from any source may find another sender's message first; the calls
  // after it could then differ from the recorded ones, so the retimer keeps the recorded sender
  // and counts the receive as reordered (the report says how many draws had one).
  const bool reordered = c.peer == kAnySource && got >= 0 && got != c.from;
  if (recorded == box.size() || box[recorded]->arrival > now_) {
    k.wait = Rank::Wait::Recv;
    k.recv_src = c.peer == kAnySource && got < 0 ? c.peer : c.from;
    k.recv_tag = c.tag;
    const double a = recorded == box.size() ? kUnknown : box[recorded]->arrival;
    if (got < 0 && wake != kUnknown)
      schedule_rank(r, after(wake - now_));
    else if (a != kUnknown)
      schedule_rank(r, after(a - now_));
    return false;
  }
  if (reordered) ++result_.reordered_receives;
  box.erase(box.begin() + std::ptrdiff_t(recorded));
  k.wait = Rank::Wait::None;
  return true;
}

Msg* Retimer::post(int r, const Call& c) {
  std::size_t charged = c.charged, size = c.size;
  if (c.kind == CallKind::IsendBlocks || c.kind == CallKind::SendBlocks) {
    std::size_t bytes = 0, ch = 0;
    const auto& blocks = t_.blocks[c.index];
    for (const TracedBlock& b : blocks) {
      bytes += std::size_t(b.size);
      ch += std::size_t(b.charged);
    }
    size = packed_blocks_size(blocks.size(), bytes);
    charged = blocks_charged(blocks.size(), ch);
  }
  if (net_params_.charge_payloads) charged = size;
  Msg& m = msgs_.emplace_back();
  m.src = r;
  m.dst = c.peer;
  m.tag = c.tag;
  m.sent_at = now_;
  inbox_[std::size_t(c.peer)].push_back(&m);
  net_.holds(r, c.peer, double(charged), m.holds);
  if (!circuit_) {
    double t = m.sent_at;
    for (const Hold& h : m.holds)
      t += h.seconds;
    m.arrival = t;
    arrived(m);
  } else {
    for (Hold& h : m.holds) {
      h.ids.resize(h.channels.size());
      for (std::size_t i = 0; i < h.channels.size(); ++i)
        h.ids[i] = channel_id(h.channels[i]);
    }
    advance(&m, now_);
  }
  return &m;
}

// Delivery::notify: the parties waiting for this message wake at its arrival.
void Retimer::arrived(Msg& m) {
  Rank& d = ranks_[std::size_t(m.dst)];
  if (d.wait == Rank::Wait::Recv && d.recv_tag == m.tag &&
      (d.recv_src == kAnySource || d.recv_src == m.src) && m.arrival < d.deadline)
    schedule_rank(m.dst, after(m.arrival - now_));
  Rank& s = ranks_[std::size_t(m.src)];
  if (s.wait == Rank::Wait::Arrival && s.awaited == &m && m.arrival < s.deadline)
    schedule_rank(m.src, after(m.arrival - now_));
}

std::uint32_t Retimer::channel_id(std::pair<int, int> c) {
  const std::uint64_t key = (std::uint64_t(std::uint32_t(c.first)) << 32) | std::uint32_t(c.second);
  auto [it, fresh] = channel_ids_.try_emplace(key, std::uint32_t(channels_.size()));
  if (fresh) channels_.emplace_back();
  return it->second;
}

void Retimer::schedule_release(std::uint32_t id) {
  Channel& c = channels_[id];
  if (c.queue.empty() || c.free_at == kUnknown || c.release_pending) return;
  c.release_pending = true;
  schedule_net(c.free_at, Event::Net::Release, nullptr, id);
}

void Retimer::hand_over(std::uint32_t id, std::vector<Msg*>& woken) {
  Channel& c = channels_[id];
  if (c.queue.empty()) {
    c.owner = nullptr;
    return;
  }
  Msg* w = c.queue.front();
  c.queue.pop_front();
  c.owner = w;
  c.free_at = kUnknown;
  ++w->next_channel;
  woken.push_back(w);
}

void Retimer::advance(Msg* m, double t) {
  if (m->holds.empty()) {
    m->arrival = t;
    arrived(*m);
    return;
  }
  for (;;) {
    const Hold& h = m->holds[m->stage];
    while (m->next_channel < h.ids.size()) {
      const std::uint32_t id = h.ids[m->next_channel];
      Channel& c = channels_[id];
      if (c.owner && !(c.free_at <= t && c.queue.empty())) {
        c.queue.push_back(m);
        schedule_release(id);
        return;
      }
      c.owner = m;
      c.free_at = kUnknown;
      ++m->next_channel;
    }
    const double end = t + h.seconds;
    if (!end_hold(m, end)) return;
    t = end;
  }
}

bool Retimer::end_hold(Msg* m, double end) {
  const Hold& h = m->holds[m->stage];
  for (const std::uint32_t id : h.ids) {
    channels_[id].free_at = end;
    schedule_release(id);
  }
  if (m->stage + 1 == m->holds.size()) {
    m->arrival = end;
    arrived(*m);
    return false;
  }
  ++m->stage;
  m->next_channel = 0;
  if (!h.channels.empty() || !m->holds[m->stage].channels.empty()) {
    schedule_net(end, Event::Net::NextStage, m, 0);
    return false;
  }
  return true;
}

void Retimer::process(const Event& e) {
  std::vector<Msg*> woken;
  if (e.net == Event::Net::NextStage) {
    const auto& prev = e.m->holds[e.m->stage - 1].ids;
    for (auto it = prev.rbegin(); it != prev.rend(); ++it)
      if (channels_[*it].owner == e.m) hand_over(*it, woken);
    advance(e.m, e.time);
  } else {
    Channel& c = channels_[e.channel];
    c.release_pending = false;
    if (c.owner && c.free_at <= e.time)
      hand_over(e.channel, woken);
    else
      schedule_release(e.channel);
  }
  for (Msg* w : woken)
    advance(w, e.time);
}

void Retimer::finish() {
  for (std::size_t r = 0; r < ranks_.size(); ++r)
    if (!ranks_[r].done) {
      diverge(RetimedRun::Status::Diverged,
              "node " + std::to_string(r) + " still waiting when the retimed run ended");
      return;
    }
  double end = 0;
  for (const Rank& k : ranks_)
    end = std::max(end, k.finish);
  result_.virtual_time_s = end;
  for (int r = 0; r < m_.nodes && std::size_t(r) < ranks_.size(); ++r) {
    const Rank& k = ranks_[std::size_t(r)];
    if (k.timed)
      result_.timed_s =
          std::max(result_.timed_s, (k.timed_ended ? k.timed_end : k.finish) - k.timed_start);
  }
  std::vector<std::uint32_t> order; // the report's: each rank's order, ranks in turn
  for (const Rank& k : ranks_)
    for (const std::uint32_t id : k.order)
      if (std::find(order.begin(), order.end(), id) == order.end()) order.push_back(id);
  for (const std::uint32_t id : order) {
    double mx = 0;
    for (const Rank& k : ranks_)
      if (k.entered[id]) mx = std::max(mx, k.totals[id]);
    result_.phase_names.push_back(t_.strings[id]);
    result_.phase_max_s.push_back(mx);
  }
}

} // namespace

std::string retimable(Fidelity fidelity, const NetworkParams& net) {
  if (fidelity == Fidelity::Flow) return "the flow fidelity shares links through SimGrid's solver";
  if (net.half_duplex_limited())
    return "links whose directions slow each other down (the T800's) are dated by the simulator";
  return "";
}

std::string retimable(const RetimeMachine& m) {
  if (std::string why = retimable(m.fidelity, m.net); !why.empty()) return why;
  return m.cost.empty() ? "no cost table" : "";
}

RetimedRun retime(const CallTrace& trace, const RetimeMachine& m, const ModelDraw& draw) {
  return Retimer(trace, m, draw).run();
}

} // namespace zc
