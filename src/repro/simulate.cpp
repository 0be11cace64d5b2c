#include "repro/simulate.hpp"

#include "repro/paper_figures.hpp"
#include "sim/simulation.hpp"

namespace zc {

void attach_paper_figures(nlohmann::json& report) {
  if (auto paper = paper_figures_for(report); !paper.empty()) report["paper"] = paper;
}

nlohmann::json simulate_point(const SimConfig& cfg) {
  SimResult r = run_simulation(cfg);
  attach_paper_figures(r.report);
  return r.report;
}

std::vector<nlohmann::json>
simulate_batch(const std::vector<SimConfig>& points, int jobs,
               const std::function<void(const BatchProgress&)>& progress) {
  return run_batch(points, jobs, simulate_point, progress);
}

} // namespace zc
