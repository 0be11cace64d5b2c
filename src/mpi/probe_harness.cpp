#include "mpi/probe_harness.hpp"

#include <time.h>

#include <algorithm>

#include "mpi/probe_groups.hpp"
#include "scene/load.hpp"

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define ZC_CALLGRIND 1
#endif

namespace zc::cpu_probe {

namespace {

// This thread's CPU time: what a loop costs the CPU, whatever else the machine runs meanwhile (on
// an idle machine, its wall-clock time).
double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

} // namespace

void Probe::time(std::size_t block, const std::string& what, std::function<void()> prep,
                 std::function<void(Counters&)> fn) {
  jobs.push_back({block,
                  std::string(loop_blocks()[block].name) + " " + what,
                  std::move(prep),
                  std::move(fn),
                  {},
                  {},
                  {}});
}

void Probe::round(bool alone) {
  for (Job& j : jobs) {
#ifdef ZC_CALLGRIND
    const std::string dump_name = "probe loop: " + j.name;
#endif
    double spent = 0;
    do {
      j.prep();
      j.c = Counters{};
#ifdef ZC_CALLGRIND
      CALLGRIND_ZERO_STATS;
#endif
      const double t0 = cpu_now();
      j.fn(j.c);
      const double s = cpu_now() - t0;
#ifdef ZC_CALLGRIND
      CALLGRIND_DUMP_STATS_AT(dump_name.c_str());
#endif
      (alone ? j.t_alone : j.t).push_back(s);
      spent += s;
    } while (spent < min_s / kRounds);
  }
}

void Probe::run() {
  for (int r = 0; r < kRounds; ++r) {
    if (ranks.times_alone) round(true);
    ranks.wait();
    round(false);
    ranks.wait();
  }
  const auto median = [](std::vector<double>& t) {
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  };
  for (Job& j : jobs) {
    loops.push_back({j.block, j.name, j.c, median(j.t), j.t.size()});
    if (!j.t_alone.empty())
      loops_alone.push_back({j.block, j.name, j.c, median(j.t_alone), j.t_alone.size()});
  }
  jobs.clear();
}

ProbeScene load_probe_scene(const std::string& path, int size) {
  LoadOptions lo;
  lo.width = lo.height = size;
  ProbeScene ps{load_scene(path, lo), "", size};
  ps.name = ps.scene.path.substr(ps.scene.path.find_last_of('/') + 1) + " " + std::to_string(size) +
            "x" + std::to_string(size);
  return ps;
}

// Every vertex of `s` projected by `nr` (the loops' inputs; their counts are not timed).
std::vector<ProjectedVertex> probe_projected_vertices(const NodeRenderer& nr, const Scene& s) {
  std::vector<ProjectedVertex> pv(s.vertices.size());
  Counters ignored;
  for (std::size_t i = 0; i < pv.size(); ++i)
    pv[i] = nr.project(s.vertices[i], ignored);
  return pv;
}

} // namespace zc::cpu_probe
