#include "sim/retimer.hpp"

#include <algorithm>

namespace zc::retiming {

Retimer::Retimer(const CallTrace& t, const RetimeMachine& m, const ModelDraw& d)
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

RetimedRun Retimer::run() {
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

// RankWaits::notify: the parties waiting for this message wake at its arrival.
void Retimer::arrived(Msg& m) {
  Rank& d = ranks_[std::size_t(m.dst)];
  if (d.wait == Rank::Wait::Recv && d.recv_tag == m.tag &&
      (d.recv_src == kAnySource || d.recv_src == m.src) && m.arrival < d.deadline)
    schedule_rank(m.dst, after(m.arrival - now_));
  Rank& s = ranks_[std::size_t(m.src)];
  if (s.wait == Rank::Wait::Arrival && s.awaited == &m && m.arrival < s.deadline)
    schedule_rank(m.src, after(m.arrival - now_));
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

} // namespace zc::retiming
