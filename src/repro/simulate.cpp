#include "repro/simulate.hpp"

#include "repro/paper_figures.hpp"
#include "sim/simulation.hpp"

namespace zc {

void attach_paper_figures(nlohmann::json& report) {
  if (auto paper = paper_figures_for(report); !paper.empty()) report["paper"] = paper;
}

namespace {
std::vector<std::string>& batch_simgrid_args() {
  static std::vector<std::string> a;
  return a;
}
} // namespace

void set_batch_simgrid_args(std::vector<std::string> args) {
  batch_simgrid_args() = std::move(args);
}

nlohmann::json simulate_point(const SimConfig& cfg) {
  const auto& extra = batch_simgrid_args();
  SimResult r;
  if (extra.empty()) {
    r = run_simulation(cfg);
  } else {
    SimConfig c = cfg;
    c.simgrid_args.insert(c.simgrid_args.end(), extra.begin(), extra.end());
    r = run_simulation(c);
  }
  attach_paper_figures(r.report);
  return r.report;
}

std::vector<nlohmann::json>
simulate_batch(const std::vector<SimConfig>& points, int jobs,
               const std::function<void(const BatchProgress&)>& progress) {
  return run_batch(points, jobs, simulate_point, progress);
}

} // namespace zc
