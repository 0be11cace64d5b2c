#pragma once
// The simulated interconnect: moves a message of m bytes from one rank to another, taking the
// virtual time the machine model and the fidelity say. Ranks 0..P-1 are nodes, P is the host
// computer (srm), linked to node 0.
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <simgrid/s4u.hpp>

#include "machine/machine.hpp"
#include "run/fidelity.hpp"
#include "run/sim_cost.hpp"

namespace zc {

// One stretch of a message's way: its channels (circuit fidelity only) held together for `seconds`.
// A message is a sequence of holds: one per hop under store-and-forward, one for the whole path
// under circuit switching, plus the host link for the host computer's messages.
struct Hold {
  std::vector<std::pair<int, int>> channels; // in acquisition order (dimension order on a cube)
  std::vector<std::uint32_t> ids; // Delivery's index of each channel, written once a message
  double seconds = 0;             // with the reverse directions idle
  // On links whose directions slow each other down (NetworkParams::half_duplex_limited): after
  // fixed_s, `bytes` cross the directed `links` at a rate the reverse directions' traffic decides
  // (DuplexLinks); empty otherwise, and `seconds` is the whole hold.
  std::vector<std::pair<int, int>> links;
  double fixed_s = 0, bytes = 0;
};

class SimNetwork {
public:
  // `cost` counts the transfers' SimGrid activities (SimCost); it must outlive this.
  SimNetwork(const NetworkParams& params, Topology topo, int nodes, Fidelity fidelity,
             std::vector<simgrid::s4u::Host*> hosts, SimCost& cost);

  // Blocks the calling actor for the duration of the transfer (the flow fidelity: SimGrid shares
  // the links' bandwidth).
  void transfer(int src, int dst, double bytes);
  // The holds of a message under the analytic and circuit fidelities, whose times zcube computes
  // itself; channels are listed under circuit only. Written over `out`, whose holds keep their
  // vectors' capacity (Delivery reuses a message's for the next one).
  void holds(int src, int dst, double bytes, std::vector<Hold>& out) const;

  const NetworkParams& params() const { return p_; }
  Topology topology() const { return topo_; }
  int nodes() const { return nodes_; }

private:
  void node_transfer(int src, int dst, double bytes);
  // Holds are written at out[n], n counting those kept.
  void node_holds(int src, int dst, double bytes, std::vector<Hold>& out, std::size_t& n) const;
  void finish_hold(std::vector<Hold>& out, std::size_t& n, double fixed, double bytes,
                   bool node_links) const;
  void sleep(double seconds);
  void hold(const std::vector<std::pair<int, int>>& channels, double seconds, double flow_bytes,
            int flow_src, int flow_dst);
  simgrid::s4u::MutexPtr channel(int a, int b);

  NetworkParams p_;
  Topology topo_;
  int nodes_;
  Fidelity fid_;
  std::vector<simgrid::s4u::Host*> hosts_; // nodes then srm
  SimCost& cost_;
  std::map<std::pair<int, int>, simgrid::s4u::MutexPtr> channels_;
  mutable std::vector<std::pair<int, int>> route_; // node_holds' scratch (capacity kept)
};

} // namespace zc
