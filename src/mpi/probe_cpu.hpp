#pragma once
// The probe's CPU measurement (mpi/probe.hpp): every counted cost timed on zcube's own loops, the
// code the algorithms call (projection, set-up, the scanline z-buffer, span lists and the active
// pixel z-buffer, a fresh frame buffer, both merges, the final pixels packed and pasted,
// tessellation, the load estimate), on scenes none of the validation workloads uses, at their
// sizes. The loops are solved in a fixed order, each block of loops for its own cost groups with
// the groups measured before it subtracted (docs/machines.md, "How the probe measures the CPU").
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "machine/machine.hpp"

namespace zc {

// What the probe found on this rank's CPU: seconds per counted operation, and the multiplier of
// each of the probe's cost groups on its prior table (what `cost` scales).
struct CpuCosts {
  CostTable cost;
  std::vector<double> multipliers;
};

// The CPU's costs on this rank. `log` receives every timed loop (its counters, seconds and the
// fitted prediction). `alone`: the multipliers of a probe of the same loops with the machine's
// other cores idle (rank 0 alone); given, a block of several groups keeps their alone split and
// fits one slowdown over it (docs/machines.md, "How the probe measures the CPU").
CpuCosts measure_cpu(const std::string& root, double min_seconds, nlohmann::json& log,
                     const std::vector<double>& alone = {});

// Maps and touches `bytes` of heap before anything is timed and keeps them (every allocation from
// the heap, none given back): the probe's loops and the MPI runs then find their buffers in memory
// that is already there, as a 1990 node's physical memory was, instead of paying the host's demand
// paging (a page fault and a zeroed page at a buffer's first touch) in whichever loop touches a
// fresh buffer first. The probe and the MPI runs both call it.
void premap_heap(std::size_t bytes);

} // namespace zc
