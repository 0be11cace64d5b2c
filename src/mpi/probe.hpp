#pragma once
// `mpirun -np P zcube probe --out cluster.xml`: measures the machine the MPI processes run on and
// writes a zcube platform of it, so `zcube run --machine cluster.xml` predicts it.
//  - Network: ping-pong between rank 0 and every other rank over message sizes 0 B..1 MiB; the
//    one-way time is half the best round trip of several. Short start-up = the mean one-way time
//    of messages up to 100 B; long start-up and per-byte cost = least squares over the larger
//    ones. Every pair is taken alike (a switched cluster: per-hop cost 0).
//  - CPU: every rank times counted kernels of the real renderer (vertex transforms alone,
//    triangle set-up alone, whole renders of the teapot and the bunny at several sizes), a
//    clear, a frame-buffer merge and a memory copy, and fits one multiplier of the 80386 prior
//    table per probe group (vertex, triangle, spans, pixels, clear, merge, packing; NNLS on
//    relative errors, pulled weakly towards one overall ratio); rank 0 averages the ranks.
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
