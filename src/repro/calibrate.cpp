// `zcube calibrate`: the fit (calibrate_fit.cpp), its prediction of Charles et al.
// (calibrate_charles.cpp) and its plausibility (calibrate_plausibility.cpp) put together as
// fit.json, and the model selection among sets of fixed groups.
#include "repro/calibrate.hpp"

#include <cmath>
#include <tuple>

#include "machine/calibrated_costs.hpp"
#include "machine/cpu_model.hpp"
#include "machine/machine.hpp"
#include "repro/calibrate_charles.hpp"
#include "repro/calibrate_fit.hpp"
#include "repro/calibrate_plausibility.hpp"
#include "repro/calibrate_runs.hpp"
#include "repro/paper_figures.hpp"

namespace zc {

namespace {

using calibration::KurcFit;

nlohmann::json table_json(CostTable t) {
  nlohmann::json j = nlohmann::json::object();
  for (auto& [id, v] : t.fields())
    j[id.substr(5)] = *v;
  return j;
}

nlohmann::json kurc_targets(const KurcFit& f) {
  nlohmann::json targets = nlohmann::json::array();
  for (std::size_t i = 0; i < f.last.size(); ++i) {
    const double pr = f.first[i].time, fi = f.last[i].time, pa = f.last[i].paper;
    targets.push_back({{"id", f.last[i].id},
                       {"machine", "ipsc2"},
                       {"quantity", "phase_ms"},
                       {"paper", pa * 1e3},
                       {"prior", pr * 1e3},
                       {"fitted", fi * 1e3},
                       {"rel_error_prior", (pr - pa) / pa},
                       {"rel_error_fitted", (fi - pa) / pa}});
  }
  return targets;
}

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& x : v) {
    if (!out.empty()) out += ",";
    out += x;
  }
  return out;
}

// Cross-validates every candidate set of fixed groups; returns the table and the chosen set.
std::pair<nlohmann::json, std::vector<std::string>> select_model(const CalibrationOptions& o) {
  using namespace calibration;
  nlohmann::json rows = nlohmann::json::array();
  std::vector<std::string> best;
  double best_err = 1e300;
  std::size_t best_free = 0;
  for (const auto& fixed : CalibrationOptions::candidate_fixed_groups()) {
    CalibrationOptions c = o;
    c.fixed_groups = fixed;
    const nlohmann::json cv = cross_validate(c);
    std::size_t nfree = 0;
    for (std::size_t g = 0; g < cost_groups().size(); ++g)
      nfree += is_fixed(g, c) ? 0 : 1;
    const double err = cv["median_abs_rel_error"].get<double>();
    rows.push_back({{"fixed_groups", join(fixed)},
                    {"free_parameters", nfree},
                    {"median_abs_rel_error", err},
                    {"worst_abs_rel_error", cv["worst_abs_rel_error"]},
                    {"rms_rel_error", cv["rms_rel_error"]}});
    const bool better =
        err < best_err - 0.005 || (std::fabs(err - best_err) <= 0.005 && nfree < best_free);
    if (best.empty() || better) {
      best = fixed;
      best_err = err;
      best_free = nfree;
    }
  }
  return {rows, best};
}

} // namespace

std::vector<std::string> CalibrationOptions::default_fixed_groups() {
  std::vector<std::string> out;
  std::string cur;
  for (const char* p = calibrated::kFixedGroups;; ++p) {
    if (*p == ',' || *p == 0) {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
      if (*p == 0) break;
    } else {
      cur += *p;
    }
  }
  return out;
}

// Candidates around the last choice (spans and packing physical): the sorted-list merge, the
// MSA/WPA and the clear each free or kept at their physical estimate.
std::vector<std::vector<std::string>> CalibrationOptions::candidate_fixed_groups() {
  return {{"packing", "spans", "scanline", "list_merge"},
          {"packing", "spans", "scanline"},
          {"packing", "spans"},
          {"packing", "spans", "scanline", "clear"}};
}

nlohmann::json calibrate(const CalibrationOptions& opt) {
  using namespace calibration;
  CalibrationOptions o = opt;
  nlohmann::json selection;
  if (o.select) std::tie(selection, o.fixed_groups) = select_model(o);
  // The whole fit and, to validate it, the folds, side by side.
  auto fits = folds();
  if (!o.cross_validate) fits.clear();
  fits.insert(fits.begin(), {kurc_scenes(), "iPSC/2 fit"});
  std::vector<KurcFit> fitted = kurc_fits(fits, o);
  const KurcFit f = fitted.front();
  fitted.erase(fitted.begin());
  nlohmann::json fit;
  nlohmann::json groups = nlohmann::json::array(), free = nlohmann::json::array(),
                 at_bound = nlohmann::json::array();
  for (std::size_t g = 0; g < cost_groups().size(); ++g) {
    groups.push_back({{"name", cost_groups()[g].name}, {"fields", cost_groups()[g].fields}});
    if (!is_fixed(g, o)) free.push_back(cost_groups()[g].name);
    const bool bound = !is_fixed(g, o) && (f.k[g] <= plausible_low() * (1 + 1e-9) ||
                                           f.k[g] >= plausible_high() * (1 - 1e-9));
    at_bound.push_back(bound);
  }
  fit["groups"] = groups;
  fit["free_groups"] = free;
  fit["bounds"] = {plausible_low(), plausible_high()};
  fit["scale"] = f.k;
  fit["at_bound"] = at_bound;
  fit["tables"] = {{"physical_i80386", table_json(cpu_seconds(cpu_model("i80386")))},
                   {"i80386", table_json(cpu_seconds(cpu_model("i80386"), f.k))},
                   {"physical_i860xr", table_json(cpu_seconds(cpu_model("i860xr")))},
                   {"i860xr", table_json(cpu_seconds(cpu_model("i860xr"), f.k))}};
  fit["targets"] = kurc_targets(f);
  fit["iterations"] = f.iterations;
  std::vector<double> e_prior = rel_errors(f.first), e_fit = rel_errors(f.last);
  fit["rms_rel_error"] = {{"kurc_prior", rms(e_prior)}, {"kurc_fitted", rms(e_fit)}};
  fit["charles"] = charles_prediction(f.k, o);
  fit["plausibility"] = plausibility(f.k);
  if (o.cross_validate) {
    fit["crossval"] = cross_validate(fitted, o);
    fit["crossval"]["coverage"] = fold_coverage(fit["crossval"], o);
  }
  if (o.select) fit["selection"] = selection;
  fit["settings"] = {{"ridge", o.ridge},
                     {"fixed_groups", o.fixed_groups},
                     {"kurc_runs", "ipsc2, 16 nodes, cube, 400x400, circuit fidelity"},
                     {"charles_runs", "ipsc860, 1 (sequential), 8 and 16 nodes (elastic), cube, "
                                      "teapot 512x512, circuit fidelity"}};
  return fit;
}

} // namespace zc
