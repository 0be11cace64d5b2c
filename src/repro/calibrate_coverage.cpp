// How often the uncertainty model's bands (docs/uncertainty.md) hold the figures each fold of the
// cross-validation did not see: the held-out scene's six Table 2 figures, predicted at the fold's
// multipliers and priced under draws whose structural error comes from the other folds' errors.
#include <cmath>
#include <map>

#include "machine/calibrated_costs.hpp"
#include "machine/uncertainty.hpp"
#include "repro/calibrate.hpp"
#include "repro/paper_figures.hpp"
#include "repro/simulate.hpp"

namespace zc {

namespace {

constexpr int kCoverageDraws = 200;
const char* const kCoverageSchemes[] = {"pair-rs", "zbuf-exc"};
const double kLevels[] = {0.5, 0.8, 0.9};

std::string phase_of(const std::string& id) {
  return id.substr(id.rfind('/') + 1);
}

// The iPSC/2's model for fold i: the folds' spread, and the structural sigma of each phase from
// the log errors of the other folds only.
UncertaintySpec fold_spec(const nlohmann::json& folds, std::size_t i) {
  UncertaintySpec s = uncertainty_spec("ipsc2");
  s.fold_scales.clear();
  std::map<std::string, std::pair<double, int>> sq;
  double all = 0;
  int n = 0;
  for (std::size_t j = 0; j < folds.size(); ++j) {
    s.fold_scales.push_back(folds[j]["scale"].get<std::vector<double>>());
    if (j == i) continue;
    for (const auto& t : folds[j]["targets"]) {
      const double r = std::log(t["predicted_ms"].get<double>() / t["paper_ms"].get<double>());
      auto& [sum, count] = sq[phase_of(t["id"])];
      sum += r * r;
      ++count;
      all += r * r;
      ++n;
    }
  }
  s.phase_sigma.clear();
  for (const auto& [name, sc] : sq)
    s.phase_sigma[name] = std::sqrt(sc.first / sc.second);
  s.phase_sigma_default = n ? std::sqrt(all / n) : 0.0;
  return s;
}

// The run of fold i's held-out scene under `scheme` at the fold's multipliers, with its bands.
RunConfig fold_run(const nlohmann::json& fold, const std::string& scheme,
                   std::shared_ptr<const UncertaintySpec> spec, const CalibrationOptions& o) {
  RunConfig c;
  c.machine = "ipsc2";
  c.nodes = kKurcTableNodes;
  c.algorithm = scheme;
  c.scene_path = o.root + "/scenes/kurc/" + fold["fold"].get<std::string>() + ".json";
  c.width = c.height = kKurcTableSize;
  c.compare_with_sequential = false;
  ModelDraw at_fold; // the fold's multipliers, relative to the built-in (fitted) table
  const auto k = fold["scale"].get<std::vector<double>>();
  for (std::size_t g = 0; g < k.size(); ++g)
    at_fold.group_scale.push_back(k[g] / calibrated::kGroupScale[g]);
  c.draw = std::make_shared<const ModelDraw>(at_fold);
  c.band_draws = kCoverageDraws;
  c.band_spec = std::move(spec);
  return c;
}

double quantile_of(const nlohmann::json& values, double q) {
  std::vector<double> v;
  for (const auto& x : values)
    if (x.is_number()) v.push_back(x.get<double>());
  return quantile(v, q);
}

} // namespace

nlohmann::json fold_coverage(const nlohmann::json& crossval, const CalibrationOptions& o) {
  const auto& folds = crossval["folds"];
  std::vector<RunConfig> cfgs;
  for (std::size_t i = 0; i < folds.size(); ++i) {
    auto spec = std::make_shared<const UncertaintySpec>(fold_spec(folds, i));
    for (const char* sch : kCoverageSchemes)
      cfgs.push_back(fold_run(folds[i], sch, spec, o));
  }
  const auto reps = simulate_batch(cfgs, o.jobs, {}, true);
  std::map<double, int> inside;
  std::vector<double> half_widths;
  nlohmann::json figures = nlohmann::json::array();
  for (std::size_t i = 0; i < folds.size(); ++i)
    for (const auto& t : folds[i]["targets"]) {
      const std::string id = t["id"], phase = phase_of(id);
      const std::size_t run = 2 * i + (id.find("/zbuf-exc/") != std::string::npos ? 1 : 0);
      const auto& r = reps[run];
      if (r.value("status", "") != "ok" || !r.contains("bands") ||
          !r["bands"]["values"]["phases"].contains(phase))
        throw std::runtime_error("coverage: no band for " + id);
      const auto& v = r["bands"]["values"]["phases"][phase];
      const double paper = t["paper_ms"].get<double>() * 1e-3;
      nlohmann::json f = {{"id", id}, {"paper_ms", paper * 1e3}};
      for (double level : kLevels) {
        const double lo = quantile_of(v, 0.5 - level / 2), hi = quantile_of(v, 0.5 + level / 2);
        const bool in = paper >= lo && paper <= hi;
        inside[level] += in;
        f["band_" + std::to_string(int(level * 100))] = {lo * 1e3, hi * 1e3};
        if (level == 0.9) half_widths.push_back((hi - lo) / (2 * quantile_of(v, 0.5)));
      }
      figures.push_back(std::move(f));
    }
  const double n = double(figures.size());
  nlohmann::json c = {{"draws", kCoverageDraws},
                      {"figures", figures.size()},
                      {"median_half_width_90", quantile(half_widths, 0.5)},
                      {"per_figure", figures}};
  for (double level : kLevels)
    c["inside_" + std::to_string(int(level * 100))] = inside[level] / n;
  return c;
}

} // namespace zc
