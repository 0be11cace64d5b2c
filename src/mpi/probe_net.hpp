#pragma once
// The probe's network measurement (mpi/probe.hpp): a ping-pong between rank 0 and every other
// rank over the message sizes the algorithms send, fitted per protocol range as SimGrid's
// smpi/or factors are (piecewise: a start-up and a per-byte cost per size range).
#include <nlohmann/json.hpp>

namespace zc {

struct NetFit {
  // The two-protocol model a platform file carries (machine/machine.hpp NetworkParams): a start-up
  // up to short_max_bytes, another above it, one per-byte cost (the long range's).
  double short_s = 0, long_s = 0, per_byte_s = 0, short_max_bytes = 100;
  // Seconds a byte of each of two messages crossing at once (exchanges of 1-16 MiB): the fit, and
  // the fit kept within [per_byte_s, 2 per_byte_s] (one message alone; two taking turns).
  double both_busy_fit_s = 0, both_busy_per_byte_s = 0;
  nlohmann::json samples =
      nlohmann::json::array(); // peer, bytes, one_way_s (the fastest), fitted_s
  // (bounded by the larger sizes)
  nlohmann::json exchanges = nlohmann::json::array(); // peer, bytes, seconds (the fastest)
  nlohmann::json ranges = nlohmann::json::array();    // the piecewise fit: from, to, startup, rate
};

// Collective over MPI_COMM_WORLD (at least 2 ranks); the fit is meaningful at rank 0 only.
NetFit measure_network(int rank, int size);

} // namespace zc
