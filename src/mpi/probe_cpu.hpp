#pragma once
// The probe's CPU measurement (mpi/probe.hpp): every counted cost timed on zcube's own loops, the
// code the algorithms call (projection, set-up, the scanline z-buffer, span lists and the active
// pixel z-buffer, a fresh frame buffer, both merges, the final pixels packed and pasted,
// tessellation, the load estimate), on scenes none of the validation workloads uses, at their
// sizes. The loops are solved in a fixed order, each block of loops for its own probe groups with
// the groups measured before it subtracted (docs/machines.md, "How the probe measures the CPU").
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "machine/machine.hpp"

namespace zc {

// What the probe found on this rank's CPU: seconds per counted operation, and the multiplier of
// each of the probe groups (probe_groups.hpp) on its prior table (what `cost` scales).
struct CpuCosts {
  CostTable cost;
  std::vector<double> multipliers;
};

// How the probe's ranks time the loops together: each round, the rank that `times_alone` (rank 0)
// times every loop while the others wait asleep, then every rank times them at once; `wait` is
// where the ranks meet between the two (the waiting ones asleep, leaving their cores idle), and
// `share` gives every rank the multipliers the alone rank found (it passes its own, the others
// an empty list). On one rank: times_alone, and both functions trivial.
struct ProbeRanks {
  bool times_alone = true;
  std::function<void()> wait = [] {};
  std::function<std::vector<double>(const std::vector<double>&)> share =
      [](const std::vector<double>& k) { return k; };
};

// What the probe found: the costs with the machine's other cores idle (a one-node run; empty on
// a rank that does not time alone) and with every rank timing at once (several nodes, sharing
// the memory system and the last-level cache), and each fit's log (every timed loop: its
// counters, seconds and the fitted prediction).
struct CpuProbe {
  CpuCosts alone;
  CpuCosts at_once;
  nlohmann::json alone_log = nlohmann::json::object();
  nlohmann::json at_once_log = nlohmann::json::object();
};

// The CPU's costs on this rank, alone and at once, their loops timed round by round in turn
// (ProbeRanks). At once, a block of several groups keeps the split the alone rank found and fits
// one slowdown over it (docs/machines.md, "How the probe measures the CPU").
CpuProbe measure_cpu(const std::string& root, double min_seconds, const ProbeRanks& ranks);

} // namespace zc
