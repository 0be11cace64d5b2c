#pragma once
// How simulated messages are sent, waited for and received, without a SimGrid actor per message
// (the network model of the run's fidelity dates their arrivals: network_model.hpp). Under the
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
#include <memory>
#include <vector>

#include <simgrid/s4u.hpp>

#include "run/sim_cost.hpp"
#include "sim/inbox.hpp"
#include "sim/network_model.hpp"
#include "sim/rank_waits.hpp"
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
  Wakeups wakeups_;
  int ranks_;
  std::vector<Inbox> inboxes_;
  RankWaits waits_; // ranks, then the network actor
  std::unique_ptr<NetworkModel> model_;
};

} // namespace zc
