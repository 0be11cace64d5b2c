#include "repro/calibrate_fit.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>

#include "machine/cpu_model.hpp"
#include "machine/machine.hpp"
#include "repro/calibrate_runs.hpp"
#include "repro/paper_figures.hpp"
#include "repro/reproduce.hpp"
#include "util/nnls.hpp"

namespace zc::calibration {

namespace {

const char* const kSchemes[] = {"pair-rs", "zbuf-exc"};

// The 16-node runs of the given scenes (pair-rs and zbuf-exc of each, in that order) on one cost
// table: a request of kurc_reports.
struct KurcRequest {
  CostTable cost;
  std::vector<std::string> scenes;
};

// Every request's runs, made in one batch (each distinct run once). The runs already made with
// the same platform text (the same cost table) are not made again: every fold's first step runs
// the prior table on scenes the whole fit ran it on.
std::vector<std::vector<nlohmann::json>> kurc_reports(const std::vector<KurcRequest>& requests,
                                                      const CalibrationOptions& o) {
  static std::map<std::string, nlohmann::json> made;
  std::vector<std::unique_ptr<TempPlatform>> plats;
  std::vector<RunConfig> cfgs;
  std::vector<std::vector<std::string>> keys(requests.size());
  std::vector<std::string> todo;
  for (std::size_t r = 0; r < requests.size(); ++r) {
    plats.push_back(std::make_unique<TempPlatform>("ipsc2", requests[r].cost, kKurcTableNodes));
    const TempPlatform& plat = *plats.back();
    for (const auto& s : requests[r].scenes)
      for (const char* sch : kSchemes) {
        keys[r].push_back(plat.text() + '\n' + s + '\n' + sch);
        if (made.contains(keys[r].back()) ||
            std::find(todo.begin(), todo.end(), keys[r].back()) != todo.end())
          continue;
        todo.push_back(keys[r].back());
        RunConfig c;
        c.machine = plat.path();
        c.nodes = kKurcTableNodes;
        c.algorithm = sch;
        c.scene_path = o.root + "/scenes/kurc/" + s + ".json";
        c.width = c.height = kKurcTableSize;
        c.compare_with_sequential = false; // the images are tested elsewhere; this is a fit
        cfgs.push_back(c);
      }
  }
  auto reps = run_all(cfgs, o);
  for (std::size_t i = 0; i < todo.size(); ++i)
    made[todo[i]] = std::move(reps[i]);
  std::vector<std::vector<nlohmann::json>> out(requests.size());
  for (std::size_t r = 0; r < requests.size(); ++r)
    for (const auto& k : keys[r])
      out[r].push_back(made.at(k));
  return out;
}

const nlohmann::json& critical_node(const nlohmann::json& rep, const std::string& phase) {
  // The paper's figures are the maxima over the nodes.
  const nlohmann::json* crit = &rep["per_node"][0];
  double best = -1;
  for (const auto& n : rep["per_node"]) {
    const double t = n["phases"].value(phase, 0.0);
    if (t > best) {
      best = t;
      crit = &n;
    }
  }
  return *crit;
}

std::vector<PhaseRow> kurc_rows(const std::vector<nlohmann::json>& reps,
                                const std::vector<std::string>& scenes, const CostTable& physical,
                                const std::vector<double>& k) {
  std::vector<PhaseRow> rows;
  for (const auto& f : kurc_table2_p16()) {
    const auto si = std::find(scenes.begin(), scenes.end(), f.scene);
    if (si == scenes.end()) continue;
    const std::size_t ri = 2 * std::size_t(si - scenes.begin()) + (f.scheme == kSchemes[0] ? 0 : 1);
    const nlohmann::json& crit = critical_node(reps[ri], f.phase);
    PhaseRow row;
    row.id = "kurc/p16/" + f.scene + "/" + f.scheme + "/" + f.phase;
    row.scene = f.scene;
    row.time = crit["phases"].value(f.phase, 0.0);
    row.paper = f.ms * 1e-3;
    const Counters work =
        crit["phase_work"].value(f.phase, nlohmann::json::object()).get<Counters>();
    row.a = group_seconds(physical, cost_groups(), work);
    double cpu = 0;
    for (std::size_t g = 0; g < row.a.size(); ++g)
      cpu += k[g] * row.a[g];
    row.wait = row.time - cpu;
    rows.push_back(row);
  }
  return rows;
}

// One bounded least-squares step over the free groups, each within the plausible range; fixed
// groups keep their multiplier (their time moves to the right-hand side).
std::vector<double> fit_step(const std::vector<PhaseRow>& rows, const std::vector<double>& k,
                             const CalibrationOptions& o) {
  const std::size_t G = cost_groups().size();
  std::vector<std::size_t> free;
  for (std::size_t g = 0; g < G; ++g)
    if (!is_fixed(g, o)) free.push_back(g);
  Matrix A;
  std::vector<double> b;
  for (const auto& r : rows) {
    std::vector<double> line;
    double fixed_time = 0;
    for (std::size_t g = 0; g < G; ++g)
      if (is_fixed(g, o))
        fixed_time += k[g] * r.a[g];
      else
        line.push_back(r.a[g] / r.paper);
    A.push_back(line);
    b.push_back((r.paper - r.wait - fixed_time) / r.paper);
  }
  for (std::size_t i = 0; i < free.size(); ++i) {
    std::vector<double> line(free.size(), 0.0);
    line[i] = o.ridge;
    A.push_back(line);
    b.push_back(o.ridge);
  }
  const std::vector<double> x = bounded_lsq(A, b, std::vector<double>(free.size(), plausible_low()),
                                            std::vector<double>(free.size(), plausible_high()));
  std::vector<double> out = k;
  for (std::size_t i = 0; i < free.size(); ++i)
    out[free[i]] = x[i];
  return out;
}

// One fit of kurc_fits: its scenes, its name in the log, and where its iteration stands.
struct KurcFitState {
  std::vector<std::string> scenes;
  std::string label;
  KurcFit f;
  int it = 0;
  bool settled = false; // one more run at the settled multipliers, then done
  bool done = false;
};

} // namespace

bool is_fixed(std::size_t g, const CalibrationOptions& o) {
  const auto& f = o.fixed_groups;
  return std::find(f.begin(), f.end(), cost_groups()[g].name) != f.end();
}

std::vector<double> rel_errors(const std::vector<PhaseRow>& rows) {
  std::vector<double> e;
  for (const auto& r : rows)
    e.push_back((r.time - r.paper) / r.paper);
  return e;
}

// The training scenes of each leave-one-scene-out fold (every scene but the held one).
std::vector<FitScenes> folds() {
  std::vector<FitScenes> out;
  for (const auto& held : kurc_scenes()) {
    std::vector<std::string> train;
    for (const auto& s : kurc_scenes())
      if (s != held) train.push_back(s);
    out.push_back({train, "fold " + held});
  }
  return out;
}

// Leave one scene out: fit the other five (fold_fits, in kurc_scenes' order), predict the sixth's
// six figures by simulating it (the six predictions in one batch).
nlohmann::json cross_validate(const std::vector<KurcFit>& fold_fits, const CalibrationOptions& o) {
  nlohmann::json folds = nlohmann::json::array();
  std::vector<double> errs;
  const CostTable physical = prior_i386_costs();
  std::vector<KurcRequest> requests;
  for (std::size_t i = 0; i < kurc_scenes().size(); ++i)
    requests.push_back({scale_groups(physical, fold_fits[i].k), {kurc_scenes()[i]}});
  const auto reps = kurc_reports(requests, o);
  for (std::size_t i = 0; i < kurc_scenes().size(); ++i) {
    const auto& held = kurc_scenes()[i];
    const KurcFit& f = fold_fits[i];
    const auto rows = kurc_rows(reps[i], requests[i].scenes, physical, f.k);
    nlohmann::json targets = nlohmann::json::array();
    for (const auto& r : rows) {
      const double e = (r.time - r.paper) / r.paper;
      errs.push_back(e);
      targets.push_back({{"id", r.id},
                         {"paper_ms", r.paper * 1e3},
                         {"predicted_ms", r.time * 1e3},
                         {"rel_error", e}});
    }
    folds.push_back({{"fold", held}, {"scale", f.k}, {"targets", targets}});
  }
  double worst = 0;
  for (double e : errs)
    worst = std::max(worst, std::fabs(e));
  return {{"folds", folds},
          {"median_abs_rel_error", median_abs(errs)},
          {"worst_abs_rel_error", worst},
          {"rms_rel_error", rms(errs)}};
}

nlohmann::json cross_validate(const CalibrationOptions& o) {
  return cross_validate(kurc_fits(folds(), o), o);
}

// The fixed-point iteration of the linearised bounded fit, for several sets of scenes at once (the
// whole fit and the leave-one-scene-out folds): each step's runs of every fit still iterating go
// in one batch, so the folds run side by side instead of one after another. Each fit's steps are
// those it would take alone.
std::vector<KurcFit> kurc_fits(const std::vector<FitScenes>& fits, const CalibrationOptions& o) {
  const CostTable physical = prior_i386_costs();
  std::vector<KurcFitState> st;
  for (const auto& [scenes, label] : fits) {
    st.push_back({scenes, label, {}, 0, false, false});
    st.back().f.k.assign(cost_groups().size(), 1.0);
  }
  while (true) {
    std::vector<std::size_t> active;
    std::vector<KurcRequest> requests;
    for (std::size_t i = 0; i < st.size(); ++i)
      if (!st[i].done) {
        active.push_back(i);
        requests.push_back({scale_groups(physical, st[i].f.k), st[i].scenes});
      }
    if (active.empty()) break;
    const auto reps = kurc_reports(requests, o);
    for (std::size_t a = 0; a < active.size(); ++a) {
      KurcFitState& s = st[active[a]];
      KurcFit& f = s.f;
      f.last = kurc_rows(reps[a], s.scenes, physical, f.k);
      if (s.settled) { // the residuals of the final table
        s.done = true;
        continue;
      }
      if (s.it == 0) f.first = f.last;
      const double e = rms(rel_errors(f.last));
      f.iterations.push_back({{"step", s.it}, {"scale", f.k}, {"rms_rel_error", e}});
      if (o.verbose)
        std::cerr << "calibrate: " << s.label << " step " << s.it << ": rms " << e << "\n";
      if (s.it >= o.max_iterations) {
        s.done = true;
        continue;
      }
      const std::vector<double> kn = fit_step(f.last, f.k, o);
      double change = 0;
      for (std::size_t g = 0; g < kn.size(); ++g)
        change = std::max(change, std::fabs(kn[g] - f.k[g]) / std::max(f.k[g], 1e-9));
      f.k = kn;
      ++s.it;
      // One more run at the settled multipliers, so the residuals are of the final table.
      s.settled = change < 1e-4;
    }
  }
  std::vector<KurcFit> out;
  for (auto& s : st)
    out.push_back(std::move(s.f));
  return out;
}

} // namespace zc::calibration
