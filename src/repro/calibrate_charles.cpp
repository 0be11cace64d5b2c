#include "repro/calibrate_charles.hpp"

#include <memory>

#include "machine/cpu_model.hpp"
#include "repro/calibrate_runs.hpp"
#include "repro/paper_figures.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"

namespace zc::calibration {

namespace {

std::vector<double> charles_speedups(const CostTable& i860, const CalibrationOptions& o) {
  std::vector<std::unique_ptr<TempPlatform>> plats;
  std::vector<RunConfig> cfgs;
  auto add = [&](int nodes, const char* algo) {
    plats.push_back(std::make_unique<TempPlatform>("ipsc860", i860, nodes));
    RunConfig c;
    c.machine = plats.back()->path();
    c.nodes = nodes;
    c.algorithm = algo;
    c.scene_path = o.root + "/" + kCharlesTeapotScene;
    c.width = c.height = kCharlesTeapotSize;
    c.compare_with_sequential = false;
    cfgs.push_back(c);
  };
  add(1, "sequential");
  for (const auto& f : charles_teapot_speedups())
    add(f.nodes, "elastic");
  const auto reps = run_all(cfgs, o);
  // The paper's timed region (docs/papers.md): the per-picture loop for elastic.
  const double seq = timed_s(reps[0]);
  std::vector<double> s;
  for (std::size_t i = 1; i < reps.size(); ++i)
    s.push_back(seq / timed_s(reps[i]));
  return s;
}

} // namespace

nlohmann::json charles_prediction(const std::vector<double>& k, const CalibrationOptions& o) {
  const CpuModel& i860 = cpu_model("i860xr");
  const auto fitted = charles_speedups(cpu_seconds(i860, k), o);
  const auto physical = charles_speedups(cpu_seconds(i860), o);
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < charles_teapot_speedups().size(); ++i) {
    const auto& f = charles_teapot_speedups()[i];
    rows.push_back({{"id", "charles/teapot512/cube/p" + std::to_string(f.nodes)},
                    {"nodes", f.nodes},
                    {"paper", f.speedup},
                    {"predicted", fitted[i]},
                    {"predicted_physical", physical[i]},
                    {"rel_error", (fitted[i] - f.speedup) / f.speedup},
                    {"rel_error_physical", (physical[i] - f.speedup) / f.speedup}});
  }
  return rows;
}

} // namespace zc::calibration
