// The circuit network (also the analytic one on links whose directions slow each other down): a
// message's holds acquire their channels one by one in the global order, each granted first come,
// first served, and held for the whole hold (platforms/README.md); a single daemon actor, the
// network's, wakes up at the releases that someone waits for. On duplex-limited links (the Volvox's
// T800 links) the same actor dates the end of each hop's bytes as the reverse directions' traffic
// starts and stops (DuplexLinks).
#include <algorithm>
#include <bit>
#include <deque>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>

#include "sim/duplex_links.hpp"
#include "sim/network_model.hpp"

namespace zc {

namespace sg = simgrid::s4u;

namespace {

class CircuitNetwork final : public NetworkModel {
public:
  CircuitNetwork(const NetworkModelParts& p, const std::vector<sg::Host*>& hosts);
  void carry(const TransitPtr& m, double bytes) override;

private:
  // What every hold reads of a channel, 24 bytes: the channels of a 1024-node cube fit in the
  // host's cache. Its queue of waiting messages is kept apart (channel_queues_), made on first
  // contention.
  struct Channel {
    const Transit* owner = nullptr;
    double free_at = 0;        // the owner's release, kNotYet while it is still acquiring
    std::uint32_t waiting = 0; // messages in its queue
    bool release_pending = false;
  };
  struct Event {
    enum class Kind {
      NextStage,  // m releases its previous hold and starts the next one
      Release,    // this channel's owner releases it
      BytesStart, // m's bytes start crossing its hold's duplex links
      BytesEnd,   // m's bytes are across, if `version` is still m's latest end
    };
    double time;
    std::uint64_t seq;
    Kind kind;
    TransitPtr m;
    std::uint32_t channel = 0;
    std::uint64_t version = 0;
    bool operator>(const Event& o) const { return time != o.time ? time > o.time : seq > o.seq; }
  };

  // The index of the channel from c.first to c.second; every hold looks its channels up. The
  // channels are the topology's links (node a's channel k leads to neighbour(a, k)), then the host
  // link's two directions.
  std::uint32_t channel_id(std::pair<int, int> c) const {
    const auto [a, b] = c;
    const int nodes = ranks_ - 1; // the host computer is rank `nodes`
    const auto node_channels = std::uint32_t(channels_.size() - 2);
    if (a >= 0 && a < nodes && b >= 0 && b < nodes && a != b) {
      const int k = topology_ == Topology::Cube              ? std::countr_zero(unsigned(a ^ b))
                    : b == neighbour(topology_, nodes, a, 0) ? 0
                                                             : 1;
      if (std::uint32_t(k) < channels_per_node_ && neighbour(topology_, nodes, a, k) == b)
        return std::uint32_t(a) * channels_per_node_ + std::uint32_t(k);
    } else if (a == nodes && b == 0) {
      return node_channels;
    } else if (a == 0 && b == nodes) {
      return node_channels + 1;
    }
    not_a_link(c);
  }
  [[noreturn]] static void not_a_link(std::pair<int, int> c);
  void advance(const TransitPtr& m, double t);
  bool end_hold(const TransitPtr& m, double end);
  void schedule_ends(const std::vector<DuplexLinks::Change>& changes);
  void schedule(Event e);
  void schedule_release(std::uint32_t id, Channel& c);
  void hand_over(std::uint32_t id, std::vector<TransitPtr>& woken);
  std::deque<TransitPtr>& queue(std::uint32_t id);
  void process(const Event& e);
  void network_loop();

  SimNetwork& net_;
  Wakeups& wakeups_;
  RankWaits& waits_;
  SimCost& cost_;
  int ranks_;
  Topology topology_;
  std::uint32_t channels_per_node_ = 0; // channel_count(topology_, nodes)
  std::vector<Channel> channels_;       // the nodes' channels, then the host link's (channel_id)
  std::vector<std::unique_ptr<std::deque<TransitPtr>>> channel_queues_; // same index
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> events_;
  std::uint64_t event_seq_ = 0;
  std::vector<TransitPtr> woken_; // scratch of process()
  DuplexLinks duplex_;
};

CircuitNetwork::CircuitNetwork(const NetworkModelParts& p, const std::vector<sg::Host*>& hosts)
    : net_(p.net), wakeups_(p.wakeups), waits_(p.waits), cost_(p.cost), ranks_(p.net.nodes() + 1),
      topology_(p.net.topology()),
      channels_per_node_(std::uint32_t(channel_count(topology_, p.net.nodes()))),
      channels_(std::size_t(p.net.nodes()) * channels_per_node_ + 2),
      channel_queues_(channels_.size()), duplex_(p.net.params()) {
  sg::Actor::create("network", hosts.back(), [this] { network_loop(); })->daemonize();
  ++cost_.actors;
}

// The channels of every hold looked up once here, not at each acquisition and release.
void CircuitNetwork::carry(const TransitPtr& m, double bytes) {
  net_.holds(m->src, m->dst, bytes, m->holds);
  for (Hold& h : m->holds) {
    h.ids.resize(h.channels.size());
    for (std::size_t i = 0; i < h.channels.size(); ++i)
      h.ids[i] = channel_id(h.channels[i]);
  }
  advance(m, m->sent_at);
}

void CircuitNetwork::schedule(Event e) {
  Waiter& net = waits_.network();
  if (net.blocked && e.time < net.deadline) waits_.wake(net, e.time);
  events_.push(std::move(e));
}

// A release matters only to a waiter, and can be dated only once the owner holds all its channels.
void CircuitNetwork::schedule_release(std::uint32_t id, Channel& c) {
  if (c.waiting == 0 || c.free_at == kNotYet || c.release_pending) return;
  c.release_pending = true;
  schedule({c.free_at, event_seq_++, Event::Kind::Release, nullptr, id});
}

// The first waiter gets the channel (a SimGrid mutex's FIFO hand-over).
std::deque<TransitPtr>& CircuitNetwork::queue(std::uint32_t id) {
  auto& q = channel_queues_[id];
  if (!q) q = std::make_unique<std::deque<TransitPtr>>();
  return *q;
}

void CircuitNetwork::hand_over(std::uint32_t id, std::vector<TransitPtr>& woken) {
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
void CircuitNetwork::advance(const TransitPtr& m, double t) {
  if (m->holds.empty()) { // to itself
    m->arrival = t;
    waits_.arrived(*m);
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

void CircuitNetwork::not_a_link(std::pair<int, int> c) {
  throw std::logic_error("delivery: channel " + std::to_string(c.first) + " -> " +
                         std::to_string(c.second) + " is not a link");
}

// m's current hold ends at `end`: its channels are dated, then m arrives or goes on. Returns true
// when its next stage can start at `end` at once (no channel to release or acquire).
bool CircuitNetwork::end_hold(const TransitPtr& m, double end) {
  const Hold& h = m->holds[m->stage];
  for (const std::uint32_t id : h.ids) {
    Channel& c = channels_[id];
    c.free_at = end;
    schedule_release(id, c);
  }
  if (m->stage + 1 == m->holds.size()) {
    m->arrival = end;
    waits_.arrived(*m);
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

void CircuitNetwork::schedule_ends(const std::vector<DuplexLinks::Change>& changes) {
  for (const auto& c : changes)
    schedule({c.end, event_seq_++, Event::Kind::BytesEnd, c.m, 0, c.version});
}

void CircuitNetwork::process(const Event& e) {
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

void CircuitNetwork::network_loop() {
  Waiter& self = waits_.network();
  double reached = kNever, now = wakeups_.now();
  for (;;) {
    // Processing does not yield: the clock stays at `now` until block().
    while (!events_.empty() && events_.top().time <= std::max(now, reached)) {
      const Event e = events_.top();
      events_.pop();
      process(e);
    }
    now = wakeups_.now();
    reached = waits_.block(self, events_.empty() ? kNotYet : events_.top().time, now);
  }
}

} // namespace

std::unique_ptr<NetworkModel> circuit_network(const NetworkModelParts& p,
                                              const std::vector<sg::Host*>& hosts) {
  return std::make_unique<CircuitNetwork>(p, hosts);
}

} // namespace zc
