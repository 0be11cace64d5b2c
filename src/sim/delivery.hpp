#pragma once
// How simulated messages travel and are received, without a SimGrid actor per message. Under the
// analytic and circuit fidelities zcube computes every arrival time itself: a message waits in its
// destination's Inbox until its arrival, and ranks wait (Wakeups: suspended, no SimGrid activity)
// until the earliest arrival that concerns them, moved earlier when a message that concerns them is
// sent meanwhile; computing is such a wait too. Circuit contention is
// decided by zcube's own channel bookkeeping: the channels of a hold are acquired one by one in the
// global order, each granted first come, first served, and held for the whole hold
// (platforms/README.md); a single daemon actor wakes up at the releases that someone waits for. On
// links whose directions slow each other down (the Volvox's T800 links), the same actor dates the
// end of each hop's bytes as the reverse directions' traffic starts and stops (DuplexLinks), under
// analytic as under circuit. Only the flow fidelity needs SimGrid's bandwidth sharing, so there a
// message crosses the links in an actor (a courier, reused for its node's next message).
#include <bit>
#include <cstdint>
#include <deque>
#include <memory>
#include <queue>
#include <vector>

#include <simgrid/s4u.hpp>

#include "machine/topology.hpp"
#include "sim/duplex_links.hpp"
#include "sim/inbox.hpp"
#include "sim/sim_cost.hpp"
#include "sim/sim_network.hpp"
#include "sim/transit.hpp"
#include "sim/wakeups.hpp"

namespace zc {

class Delivery {
public:
  // message_stack_kib: the stack of a message's actor under the flow fidelity (KiB, capped at
  // contexts/stack-size). `cost` counts what delivering costs the simulator (SimCost); it must
  // outlive this.
  Delivery(SimNetwork& net, Fidelity fidelity, std::vector<simgrid::s4u::Host*> hosts,
           unsigned message_stack_kib, SimCost& cost);

  // Sends at the current virtual time; the message's arrival is set now or later. The network is
  // charged m.charged bytes, whatever the payload's size. A message of several blocks comes as
  // `blocks` (bundle true), charged m.charged. Both are moved from.
  TransitPtr post(int src, int dst, int tag, Message&& m, Blocks&& blocks = {},
                  bool bundle = false);
  // Blocks rank `self` until message m has arrived (a sender's completion). `now` is the virtual
  // time on entry, and on return.
  void await_arrival(int self, const Transit& m, double& now);
  // Blocks rank `self` until a message from src (or kAnySource) with this tag can be taken. `now`
  // is the virtual time on entry, and on return.
  TransitPtr receive(int self, int src, int tag, double& now);
  // The virtual time (Wakeups::now).
  double now() const { return wakeups_.now(); }
  // Rank `self` computes for `seconds` (as SimGrid's sleep_for would take).
  void compute(int self, double seconds);
  // The run is over (its last rank finished, or it failed): no wake-up may move the clock further.
  void stop() { wakeups_.cancel_all(); }

private:
  // One per rank: where its actor blocks, and what it waits for (to notify only when it matters).
  struct Waiter {
    Wakeups::Sleeper sleeper;
    bool blocked = false, receiving = false;
    int src = 0, tag = 0;
    const Transit* send = nullptr;
    double deadline = kNotYet;
  };
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

  // Both return the deadline reached and set `now` to the time they return at.
  double block(Waiter& w, double deadline, double& now);
  double sleep_until(Waiter& w, double deadline, double& now);
  void notify(Waiter& w, const Transit& m);
  // A blocked waiter's wake-up moved to `t`, earlier than its deadline.
  void wake(Waiter& w, double t);
  void arrived(Transit& m);
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
  // Circuit fidelity, and analytic on links whose directions slow each other down.
  void advance(const TransitPtr& m, double t);
  bool end_hold(const TransitPtr& m, double end);
  void schedule_ends(const std::vector<DuplexLinks::Change>& changes);
  void schedule(Event e);
  void schedule_release(std::uint32_t id, Channel& c);
  void hand_over(std::uint32_t id, std::vector<TransitPtr>& woken);
  std::deque<TransitPtr>& queue(std::uint32_t id);
  void process(const Event& e);
  void network_loop();
  // Flow fidelity: the actor that carries a message across SimGrid's links (carry()).
  struct Courier {
    simgrid::s4u::ActorPtr actor;
    TransitPtr job; // the message to carry, null while idle
    double bytes = 0;
  };
  void carry(const TransitPtr& m, double bytes);
  void courier_loop(Courier& c);

  SimNetwork& net_;
  Fidelity fidelity_;
  SimCost& cost_;
  Wakeups wakeups_;
  std::vector<simgrid::s4u::Host*> hosts_;
  unsigned message_stack_kib_;
  int ranks_;
  std::vector<Inbox> inboxes_;
  std::vector<Waiter> waiters_; // ranks, then the network actor
  Topology topology_;
  std::uint32_t channels_per_node_ = 0; // channel_count(topology_, nodes)
  std::vector<Channel> channels_;       // the nodes' channels, then the host link's (channel_id)
  std::vector<std::unique_ptr<std::deque<TransitPtr>>> channel_queues_; // same index
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> events_;
  std::uint64_t event_seq_ = 0;
  std::vector<TransitPtr> woken_; // scratch of process()
  std::vector<std::unique_ptr<Courier>> couriers_;
  std::vector<std::vector<Courier*>> idle_couriers_; // by sending rank
  bool events_driven_; // circuit, or any fidelity zcube times on half-duplex-limited links
  DuplexLinks duplex_;
};

} // namespace zc
