#pragma once
// The probe's timing harness (probe_cpu.hpp): loops registered by the workload builders
// (probe_workloads.hpp), then timed round by round on this thread's CPU clock, alone and with
// every rank at once; and the scenes the workloads are made of.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "mpi/probe_cpu.hpp"
#include "raster/renderer.hpp"
#include "scene/scene.hpp"
#include "util/counters.hpp"

namespace zc::cpu_probe {

// A timed loop: its block, its counters (one call's) and its median time a call.
struct Loop {
  std::size_t block;
  std::string name;
  Counters c;
  double seconds;
  std::size_t calls;
};

struct Probe {
  double min_s;
  const ProbeRanks& ranks;
  std::vector<Loop> loops;       // every rank at once
  std::vector<Loop> loops_alone; // rank 0 alone (times_alone), the other ranks waiting

  struct Job {
    std::size_t block;
    std::string name;
    std::function<void()> prep;
    std::function<void(Counters&)> fn;
    Counters c;
    std::vector<double> t, t_alone;
  };
  std::vector<Job> jobs;

  // Registers a loop: fn timed, `prep` run before each call untimed, the counters fn counts
  // recorded. run() times the registered loops.
  void time(std::size_t block, const std::string& what, std::function<void()> prep,
            std::function<void(Counters&)> fn);
  void time(std::size_t block, const std::string& what, std::function<void(Counters&)> fn) {
    time(
        block, what, [] {}, std::move(fn));
  }

  // Every registered loop in turn, each called until it has run a third of min_s; its times go
  // to `alone` or to the at-once series. Under callgrind every call's instructions are dumped
  // apart, named after the loop (scripts/probe_instructions.py).
  void round(bool alone);

  // The registered loops, three rounds; each round times them first on rank 0 alone, then on
  // every rank at once. A change of the machine's load meanwhile falls on all the loops, not on
  // those timed last (the blocks subtract one loop's costs from another's), and on the alone and
  // at-once times alike: their ratio, what a node loses to the others sharing the memory system,
  // is taken in the same minutes (timed one after the other, a drift of the host between the two
  // series can make a rank look faster with the other cores busy than alone). A loop's time is
  // the median of its calls.
  static constexpr int kRounds = 3;
  void run();
};

// A scene loaded at a size (the probe's input, not a rendered picture), and the name its loops
// carry: file name and size.
struct ProbeScene {
  Scene scene;
  std::string name;
  int size;
};
ProbeScene load_probe_scene(const std::string& path, int size);

// Every vertex of `s` projected by `nr` (the loops' inputs; their counts are not timed).
std::vector<ProjectedVertex> probe_projected_vertices(const NodeRenderer& nr, const Scene& s);

} // namespace zc::cpu_probe
