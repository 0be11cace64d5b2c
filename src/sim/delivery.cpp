#include "sim/delivery.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include <xbt/config.hpp>

namespace zc {

namespace sg = simgrid::s4u;

namespace {
constexpr double kNever = -std::numeric_limits<double>::infinity();
} // namespace

Delivery::Delivery(SimNetwork& net, Fidelity fidelity, std::vector<sg::Host*> hosts,
                   unsigned message_stack_kib, SimCost& cost)
    : net_(net), fidelity_(fidelity), cost_(cost),
      wakeups_(simgrid::config::get_value<double>("surf/precision"), cost),
      hosts_(std::move(hosts)),
      message_stack_kib_(std::min(
          message_stack_kib, unsigned(simgrid::config::get_value<int>("contexts/stack-size")))),
      ranks_(net.nodes() + 1), inboxes_(std::size_t(ranks_), Inbox(ranks_)), waiters_(ranks_ + 1),
      events_driven_(fidelity == Fidelity::Circuit ||
                     (fidelity == Fidelity::Analytic && net.params().half_duplex_limited())),
      duplex_(net.params()) {
  if (fidelity == Fidelity::Flow) idle_couriers_.resize(std::size_t(ranks_));
  topology_ = net.topology();
  channels_per_node_ = std::uint32_t(channel_count(topology_, net.nodes()));
  if (events_driven_) {
    channels_.resize(std::size_t(net.nodes()) * channels_per_node_ + 2);
    channel_queues_.resize(channels_.size());
  }
  for (int i = 0; i <= ranks_; ++i)
    waiters_[std::size_t(i)].sleeper.order = i; // ranks, then the network's actor
  if (events_driven_) {
    sg::Actor::create("network", hosts_.back(), [this] { network_loop(); })->daemonize();
    ++cost_.actors;
  }
}

// A rank blocks until its wake-up: its deadline, or an earlier one that a message moved it to
// (notify). Nobody else can run between the decision to block and the block itself (actors take
// turns on one thread, and a rank yields only in Wakeups::wait).
double Delivery::block(Waiter& w, double deadline, double& now) {
  w.blocked = true;
  w.deadline = deadline;
  if (deadline != kNotYet) wakeups_.set_until(w.sleeper, deadline);
  const double reached = wakeups_.wait(w.sleeper);
  w.blocked = false;
  now = wakeups_.now();
  return reached;
}

void Delivery::notify(Waiter& w, const Transit& m) {
  if (!w.blocked || !(m.arrival < w.deadline)) return;
  const bool wanted =
      w.send == &m || (w.receiving && w.tag == m.tag && (w.src == kAnySource || w.src == m.src));
  if (wanted) wake(w, m.arrival);
}

// The waiter wakes when the message it wants has arrived, at the date a wait set now for that
// arrival would end at (as when it was woken now and then slept until the arrival). It stays
// blocked: a message arriving earlier still moves its wake-up.
void Delivery::wake(Waiter& w, double t) {
  w.deadline = t;
  wakeups_.set_until(w.sleeper, t);
}

void Delivery::arrived(Transit& m) {
  notify(waiters_[m.dst], m);
  notify(waiters_[m.src], m);
}

TransitPtr Delivery::post(int src, int dst, int tag, Message&& msg, Blocks&& blocks, bool bundle) {
  TransitPtr m = TransitPtr::make();
  m->src = src;
  m->dst = dst;
  m->tag = tag;
  m->data = std::move(msg.payload);
  m->blocks = std::move(blocks);
  m->bundle = bundle;
  m->charged = msg.charged;
  m->sent_at = wakeups_.now();
  const double bytes = double(m->charged);
  if (fidelity_ == Fidelity::Analytic && !events_driven_) {
    double t = m->sent_at;
    net_.holds(src, dst, bytes, m->holds);
    for (const Hold& h : m->holds)
      t += h.seconds;
    m->arrival = t;
    inboxes_[dst].push(m);
    notify(waiters_[dst], *m);
  } else if (events_driven_) {
    net_.holds(src, dst, bytes, m->holds);
    for (Hold& h : m->holds) { // looked up once here, not at each acquisition and release
      h.ids.resize(h.channels.size());
      for (std::size_t i = 0; i < h.channels.size(); ++i)
        h.ids[i] = channel_id(h.channels[i]);
    }
    inboxes_[dst].push(m);
    advance(m, m->sent_at);
  } else {
    m->holds.clear();
    inboxes_[dst].push(m);
    carry(m, bytes);
  }
  return m;
}

// Under the flow fidelity a message crosses SimGrid's links in an actor of its own (a courier),
// on a small stack: its code is a few calls deep, and SimGrid's default (8 MiB, mapped and
// unmapped apart) cost the host a mmap, two mprotects, a munmap and fresh pages each. A courier
// that has delivered waits for the next message of its node instead of ending: SimGrid clears a
// new actor's stack (calloc) and unwinds an ending one with an exception, the host cost of most
// messages. It starts at once as a new actor would (SimGrid runs it at this virtual time, after
// the actors already due), on the sender's host.
void Delivery::carry(const TransitPtr& m, double bytes) {
  auto& idle = idle_couriers_[std::size_t(m->src)];
  if (!idle.empty()) {
    Courier* c = idle.back();
    idle.pop_back();
    c->job = m;
    c->bytes = bytes;
    c->actor->resume();
    return;
  }
  couriers_.push_back(std::make_unique<Courier>());
  Courier* c = couriers_.back().get();
  c->job = m;
  c->bytes = bytes;
  c->actor = sg::Actor::init("msg", hosts_[std::size_t(m->src)])
                 ->set_stacksize(message_stack_kib_)
                 ->start([this, c] { courier_loop(*c); });
  c->actor->daemonize(); // an idle courier does not keep the simulation going
  ++cost_.actors;
}

void Delivery::courier_loop(Courier& c) {
  for (;;) {
    TransitPtr m = std::move(c.job);
    net_.transfer(m->src, m->dst, c.bytes);
    m->arrival = wakeups_.now();
    arrived(*m);
    idle_couriers_[std::size_t(m->src)].push_back(&c);
    m.reset();
    while (!c.job) {
      ++cost_.actor_switches;
      sg::this_actor::suspend();
    }
  }
}

// A known arrival that nothing can bring forward is waited for without being marked blocked
// (nobody needs to move this rank's wake-up). As with block(), the deadline itself counts as
// reached.
double Delivery::sleep_until(Waiter& w, double deadline, double& now) {
  if (deadline - now > 0) {
    wakeups_.set_until(w.sleeper, deadline);
    wakeups_.wait(w.sleeper);
    now = wakeups_.now();
  }
  return deadline;
}

void Delivery::compute(int self, double seconds) {
  if (!(seconds > 0)) return;
  Waiter& w = waiters_[self];
  wakeups_.set_after(w.sleeper, seconds, 0);
  wakeups_.wait(w.sleeper);
}

void Delivery::await_arrival(int self, const Transit& m, double& now) {
  Waiter& w = waiters_[self];
  double reached = kNever;
  while (!(m.arrival <= std::max(now, reached))) {
    if (m.arrival != kNotYet) { // set once: only contention (circuit, flow) leaves it open
      reached = sleep_until(w, m.arrival, now);
      continue;
    }
    w.send = &m;
    reached = block(w, m.arrival, now);
    w.send = nullptr;
  }
}

TransitPtr Delivery::receive(int self, int src, int tag, double& now) {
  Waiter& w = waiters_[self];
  double reached = kNever;
  for (;;) {
    double wake = kNotYet;
    if (auto m = inboxes_[self].take(src, tag, std::max(now, reached), wake)) return m;
    // From one source, the oldest message of its tag is the one to take (nothing sent later
    // overtakes it): once its arrival is known, sleep until it. From any source, another message
    // may still arrive first.
    if (src != kAnySource && wake != kNotYet) {
      reached = sleep_until(w, wake, now);
      continue;
    }
    w.receiving = true;
    w.src = src;
    w.tag = tag;
    reached = block(w, wake, now);
    w.receiving = false;
  }
}

// --- circuit fidelity, and analytic on duplex-limited links
// ---------------------------------------

void Delivery::schedule(Event e) {
  Waiter& net = waiters_.back();
  if (net.blocked && e.time < net.deadline) wake(net, e.time);
  events_.push(std::move(e));
}

// A release matters only to a waiter, and can be dated only once the owner holds all its channels.
void Delivery::schedule_release(std::uint32_t id, Channel& c) {
  if (c.waiting == 0 || c.free_at == kNotYet || c.release_pending) return;
  c.release_pending = true;
  schedule({c.free_at, event_seq_++, Event::Kind::Release, nullptr, id});
}

// The first waiter gets the channel (a SimGrid mutex's FIFO hand-over).
std::deque<TransitPtr>& Delivery::queue(std::uint32_t id) {
  auto& q = channel_queues_[id];
  if (!q) q = std::make_unique<std::deque<TransitPtr>>();
  return *q;
}

void Delivery::hand_over(std::uint32_t id, std::vector<TransitPtr>& woken) {
  Channel& c = channels_[id];
  if (c.waiting == 0) {
    c.owner = nullptr;
    return;
  }
  auto& q = queue(id);
  TransitPtr w = std::move(q.front());
  q.pop_front();
  --c.waiting;
  c.owner = w.get();
  c.free_at = kNotYet;
  ++w->next_channel;
  woken.push_back(std::move(w));
}

// Message m, at time t (the current virtual time), acquires the channels of its current hold that
// it does not have yet; once it has them all, its end of hold is known (or, on duplex links, its
// bytes start after the hold's fixed part and DuplexLinks dates their end).
void Delivery::advance(const TransitPtr& m, double t) {
  if (m->holds.empty()) { // to itself
    m->arrival = t;
    arrived(*m);
    return;
  }
  for (;;) {
    const Hold& h = m->holds[m->stage];
    while (m->next_channel < h.ids.size()) {
      const std::uint32_t id = h.ids[m->next_channel];
      Channel& c = channels_[id];
      const bool free = !c.owner || (c.free_at <= t && c.waiting == 0);
      if (!free) {
        queue(id).push_back(m);
        ++c.waiting;
        schedule_release(id, c);
        return;
      }
      c.owner = m.get();
      c.free_at = kNotYet;
      ++m->next_channel;
    }
    if (!h.links.empty()) {
      schedule({t + h.fixed_s, event_seq_++, Event::Kind::BytesStart, m});
      return;
    }
    const double end = t + h.seconds;
    if (!end_hold(m, end)) return;
    t = end; // no channel before or after: nothing to decide at `end`
  }
}

void Delivery::not_a_link(std::pair<int, int> c) {
  throw std::logic_error("delivery: channel " + std::to_string(c.first) + " -> " +
                         std::to_string(c.second) + " is not a link");
}

// m's current hold ends at `end`: its channels are dated, then m arrives or goes on. Returns true
// when its next stage can start at `end` at once (no channel to release or acquire).
bool Delivery::end_hold(const TransitPtr& m, double end) {
  const Hold& h = m->holds[m->stage];
  for (const std::uint32_t id : h.ids) {
    Channel& c = channels_[id];
    c.free_at = end;
    schedule_release(id, c);
  }
  if (m->stage + 1 == m->holds.size()) {
    m->arrival = end;
    arrived(*m);
    return false;
  }
  ++m->stage;
  m->next_channel = 0;
  if (!h.channels.empty() || !m->holds[m->stage].channels.empty()) {
    schedule({end, event_seq_++, Event::Kind::NextStage, m});
    return false;
  }
  return true;
}

void Delivery::schedule_ends(const std::vector<DuplexLinks::Change>& changes) {
  for (const auto& c : changes)
    schedule({c.end, event_seq_++, Event::Kind::BytesEnd, c.m, 0, c.version});
}

void Delivery::process(const Event& e) {
  ++cost_.network_events;
  std::vector<TransitPtr>& woken = woken_;
  woken.clear();
  std::vector<DuplexLinks::Change> changes;
  switch (e.kind) {
  case Event::Kind::NextStage: {
    // Release the previous hold's channels in reverse order, continue, then the waiters go on.
    const Transit& m = *e.m;
    const auto& prev = m.holds[m.stage - 1].ids;
    for (auto it = prev.rbegin(); it != prev.rend(); ++it) {
      if (channels_[*it].owner == &m) hand_over(*it, woken);
    }
    advance(e.m, e.time);
    break;
  }
  case Event::Kind::Release: {
    Channel& c = channels_[e.channel];
    c.release_pending = false;
    if (c.owner && c.free_at <= e.time)
      hand_over(e.channel, woken);
    else
      schedule_release(e.channel, c); // a new owner since: its own release, once dated
    break;
  }
  case Event::Kind::BytesStart: {
    const Hold& h = e.m->holds[e.m->stage];
    duplex_.begin(e.m, h.links, h.bytes, e.time, changes);
    schedule_ends(changes);
    break;
  }
  case Event::Kind::BytesEnd:
    if (!duplex_.current(*e.m, e.version)) break; // superseded by a later rate change
    duplex_.end(*e.m, e.time, changes);
    schedule_ends(changes);
    if (end_hold(e.m, e.time)) advance(e.m, e.time);
    break;
  }
  for (const auto& w : woken)
    advance(w, e.time);
}

void Delivery::network_loop() {
  Waiter& self = waiters_.back();
  double reached = kNever, now = wakeups_.now();
  for (;;) {
    // Processing does not yield: the clock stays at `now` until block().
    while (!events_.empty() && events_.top().time <= std::max(now, reached)) {
      const Event e = events_.top();
      events_.pop();
      process(e);
    }
    now = wakeups_.now();
    reached = block(self, events_.empty() ? kNotYet : events_.top().time, now);
  }
}

} // namespace zc
