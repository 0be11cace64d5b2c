#pragma once
// A message on its way through the simulated machine: the payload (or the blocks) it shares with
// its sender, the size it is charged, and when it is fully received.
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#include "comm/comm.hpp"
#include "sim/sim_network.hpp"

namespace zc {

constexpr double kNotYet = std::numeric_limits<double>::infinity();

struct Transit {
  int src, dst, tag;
  Payload data;
  Blocks blocks;       // a message of several blocks (Comm::isend_blocks), their payloads shared
  bool bundle = false; // whether it is one
  std::size_t charged = 0; // the bytes the network is charged (comm.hpp)
  double sent_at = 0;
  double arrival = kNotYet; // virtual time of full reception, kNotYet while contention decides it
  // Progress through the circuit fidelity's holds (Delivery's channel bookkeeping).
  std::vector<Hold> holds;
  std::size_t stage = 0, next_channel = 0;
};
using TransitPtr = std::shared_ptr<Transit>;

} // namespace zc
