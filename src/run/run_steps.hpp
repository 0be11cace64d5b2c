#pragma once
// The skeleton every backend runs one run with (docs/architecture.md, "The path of one run"):
//   prepare_run   the algorithm, its options checked, the scene;
//   (execute)     the backend's own: SimGrid actors on a machine model (sim/simulation.cpp) or
//                 MPI processes (mpi/mpi_run.cpp), each node recording into a NodeRecord;
//   finish_run    the typed report from the records and pictures, the pictures checked against
//                 the sequential renderer's.
#include <chrono>
#include <string>
#include <vector>

#include "run/config.hpp"
#include "run/report.hpp"

namespace zc {

// The algorithm and its options, checked, and the scene (loaded here unless the caller has it).
struct PreparedRun {
  const Algorithm* algo = nullptr;
  AlgorithmOptions options;
  Scene loaded;                     // when the caller had none
  const Scene* preloaded = nullptr; // the caller's
  const Scene& scene() const { return preloaded ? *preloaded : loaded; }
  std::string scene_path; // as the report names it: the caller's scene's own, else as given
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
};
// `cube`: the run's links form a hypercube (or may: a platform file), as an algorithm that needs
// one asks.
PreparedRun prepare_run(const RunConfig& cfg, const Scene* preloaded, bool cube);

// What the backend's execution ended with.
struct Executed {
  std::string machine, platform, topology, fidelity; // the report's header
  int nodes = 0;
  double total_s = 0;  // the run's time: virtual, or the slowest rank's measured time
  std::string failure; // "" when the run ended well
  bool out_of_memory = false;
  std::vector<NodeRecord> records; // the P nodes, then the host computer when it ran
  std::vector<FrameImage> images;  // as the nodes handed them over
};

// The report (and the pictures, one per frame) of an executed run.
RunResult finish_run(const RunConfig& cfg, const PreparedRun& run, Executed done);

} // namespace zc
