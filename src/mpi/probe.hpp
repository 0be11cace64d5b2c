#pragma once
// `mpirun -np P zcube probe --out cluster.xml`: measures the machine the MPI processes run on and
// writes a zcube platform of it, so `zcube run --machine cluster.xml` predicts it.
//  - Network (mpi/probe_net.hpp): ping-pong between rank 0 and every other rank over the sizes
//    the algorithms send (0 B..16 MiB), the tenth percentile of many round trips; a start-up and
//    a per-byte cost per protocol range (SimGrid's smpi/or, piecewise), of which the platform
//    takes two: a start-up up to the switch point that fits best, another above it, the long
//    range's per-byte cost.
//  - CPU (mpi/probe_cpu.hpp): every rank times zcube's own loops (projection, set-up, the
//    scanline z-buffer, span lists, the active pixel z-buffer, a fresh frame buffer, both merges,
//    packing, tessellation, the load estimate) on its CPU time and fits one multiplier of the
//    80386 table per probe group (probe_groups.hpp) to them (NNLS on relative errors); twice:
//    rank 0 alone while the other ranks sleep (the platform of one node), then every rank at
//    once, averaged (the platforms of several nodes: the ranks share the cores' memory system and
//    cache).
//  - Memory: the host's physical memory shared by the ranks on it.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace zc {

struct ProbeOptions {
  std::string root;       // source tree (scenes/)
  std::string out;        // platform XML to write (with several node counts: <stem>-<P>.xml each)
  std::vector<int> nodes; // node counts to write platforms for (empty: the number of ranks)
  double seconds = 0.2;   // least time per CPU measurement
};

// Call on every rank inside an MpiSession; rank 0 writes the file and returns the measurements
// (other ranks return an empty object).
// The files written, for `nodes` = {1, 2, 4} and out = c.xml: c-1.xml, c-2.xml, c-4.xml.
std::vector<std::string> probe_outputs(const ProbeOptions& opt, int ranks);
nlohmann::json probe_cluster(const ProbeOptions& opt);

} // namespace zc
