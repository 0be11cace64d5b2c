#include "repro/calibrate.hpp"
#include "repro/simulate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <tuple>

#include "machine/calibrated_costs.hpp"
#include "machine/cpu_model.hpp"
#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "repro/paper_figures.hpp"
#include "repro/reproduce.hpp"
#include "run/batch.hpp"
#include "util/nnls.hpp"

namespace zc {

namespace {

// A platform file with a candidate cost table, for the runs of one fit step.
class TempPlatform {
public:
  TempPlatform(const std::string& machine, const CostTable& cost, int nodes) {
    MachineSpec spec = machine_spec(machine);
    spec.cost = cost;
    static int serial = 0;
    path_ = (std::filesystem::temp_directory_path() /
             ("zcube-calibrate-" + std::to_string(getpid()) + "-" + std::to_string(serial++) + "-" +
              platform_file_name(machine, nodes, Topology::Cube)))
                .string();
    text_ = platform_xml(spec, nodes, Topology::Cube);
    std::ofstream(path_) << text_;
  }
  ~TempPlatform() { std::filesystem::remove(path_); }
  TempPlatform(const TempPlatform&) = delete;
  TempPlatform& operator=(const TempPlatform&) = delete;
  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }

private:
  std::string path_, text_;
};

std::vector<nlohmann::json> run_all(const std::vector<SimConfig>& cfgs,
                                    const CalibrationOptions& o) {
  auto reps = simulate_batch(cfgs, o.jobs, {}, true); // its later steps replay the first's
  for (std::size_t i = 0; i < reps.size(); ++i)
    if (reps[i].value("status", "") != "ok")
      throw std::runtime_error("calibration run " + cfgs[i].algorithm + " on " +
                               cfgs[i].scene_path + " failed: " + reps[i].value("error", "?"));
  return reps;
}

double rms(const std::vector<double>& e) {
  double s = 0;
  for (double x : e)
    s += x * x;
  return e.empty() ? 0 : std::sqrt(s / double(e.size()));
}

double median_abs(std::vector<double> e) {
  for (double& x : e)
    x = std::fabs(x);
  std::sort(e.begin(), e.end());
  if (e.empty()) return 0;
  const std::size_t n = e.size();
  return n % 2 ? e[n / 2] : 0.5 * (e[n / 2 - 1] + e[n / 2]);
}

// ---- Kurc et al. Table 2 on the iPSC/2 --------------------------------------------------------

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
  std::vector<SimConfig> cfgs;
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
        SimConfig c;
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

// One target as a row of the linear model: the critical node's operations per group (at physical
// prices) and its time not spent computing.
struct PhaseRow {
  std::vector<double> a; // per group
  double wait = 0, time = 0, paper = 0;
  std::string id, scene;
};

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

bool is_fixed(std::size_t g, const CalibrationOptions& o) {
  const auto& f = o.fixed_groups;
  return std::find(f.begin(), f.end(), cost_groups()[g].name) != f.end();
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

struct KurcFit {
  std::vector<double> k;
  std::vector<PhaseRow> first, last; // rows at the physical estimate and at the fit
  nlohmann::json iterations = nlohmann::json::array();
};

std::vector<double> rel_errors(const std::vector<PhaseRow>& rows) {
  std::vector<double> e;
  for (const auto& r : rows)
    e.push_back((r.time - r.paper) / r.paper);
  return e;
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

// The fixed-point iteration of the linearised bounded fit, for several sets of scenes at once (the
// whole fit and the leave-one-scene-out folds): each step's runs of every fit still iterating go
// in one batch, so the folds run side by side instead of one after another. Each fit's steps are
// those it would take alone.
std::vector<KurcFit>
kurc_fits(const std::vector<std::pair<std::vector<std::string>, std::string>>& fits,
          const CalibrationOptions& o) {
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

// The training scenes of each leave-one-scene-out fold (every scene but the held one).
std::vector<std::pair<std::vector<std::string>, std::string>> folds() {
  std::vector<std::pair<std::vector<std::string>, std::string>> out;
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

// ---- Charles et al. §6 on the iPSC/860: predicted, not fitted ---------------------------------

std::vector<double> charles_speedups(const CostTable& i860, const CalibrationOptions& o) {
  std::vector<std::unique_ptr<TempPlatform>> plats;
  std::vector<SimConfig> cfgs;
  auto add = [&](int nodes, const char* algo) {
    plats.push_back(std::make_unique<TempPlatform>("ipsc860", i860, nodes));
    SimConfig c;
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

// ---- Plausibility: every fitted cost against its physical estimate ---------------------------

nlohmann::json plausibility(const std::vector<double>& k) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& name : cpu_names()) {
    const CpuModel& cpu = cpu_model(name);
    CostTable phys = cpu.cycles, fit = scale_groups(cpu.cycles, k);
    const auto pf = phys.fields(), ff = fit.fields();
    for (std::size_t i = 0; i < pf.size(); ++i) {
      const double p = *pf[i].second, f = *ff[i].second;
      rows.push_back({{"cpu", name},
                      {"operation", pf[i].first.substr(5)},
                      {"physical_cycles", p},
                      {"fitted_cycles", f},
                      {"ratio", p > 0 ? f / p : 1.0}});
    }
  }
  return rows;
}

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
