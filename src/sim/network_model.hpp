#pragma once
// How a message posted by Delivery gets its arrival date, one model a fidelity (in the manner of
// SimGrid's network_*.cpp): analytic (network_analytic.cpp: the sum of its holds, known when it is
// sent), circuit (network_circuit.cpp: channels acquired first come, first served, by an actor of
// the network's own; also analytic on links whose directions slow each other down), and flow
// (network_flow.cpp: SimGrid's bandwidth sharing, crossed by a courier actor).
#include <memory>
#include <vector>

#include <simgrid/s4u.hpp>

#include "run/sim_cost.hpp"
#include "sim/rank_waits.hpp"
#include "sim/sim_network.hpp"
#include "sim/transit.hpp"
#include "sim/wakeups.hpp"

namespace zc {

class NetworkModel {
public:
  virtual ~NetworkModel() = default;
  // m (sent now, already in its destination's inbox) crosses the network: its arrival is dated,
  // now or later, and the parties waiting for it are told (RankWaits).
  virtual void carry(const TransitPtr& m, double bytes) = 0;
};

// What every model may use; each must outlive the model.
struct NetworkModelParts {
  SimNetwork& net;
  Wakeups& wakeups;
  RankWaits& waits;
  SimCost& cost;
};

std::unique_ptr<NetworkModel> analytic_network(const NetworkModelParts& p);
// Starts the network's actor (on the host computer's host, the last of `hosts`).
std::unique_ptr<NetworkModel> circuit_network(const NetworkModelParts& p,
                                              const std::vector<simgrid::s4u::Host*>& hosts);
// message_stack_kib: the stack of a courier actor (KiB, already capped at contexts/stack-size).
std::unique_ptr<NetworkModel> flow_network(const NetworkModelParts& p,
                                           std::vector<simgrid::s4u::Host*> hosts,
                                           unsigned message_stack_kib);

} // namespace zc
