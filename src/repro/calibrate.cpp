#include "repro/calibrate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "machine/units.hpp"
#include "repro/nnls.hpp"
#include "repro/paper_figures.hpp"
#include "sim/batch.hpp"
#include "util/error.hpp"

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
    std::ofstream(path_) << platform_xml(spec, nodes, Topology::Cube);
  }
  ~TempPlatform() { std::filesystem::remove(path_); }
  TempPlatform(const TempPlatform&) = delete;
  TempPlatform& operator=(const TempPlatform&) = delete;
  const std::string& path() const { return path_; }

private:
  std::string path_;
};

std::vector<nlohmann::json> run_all(const std::vector<SimConfig>& cfgs,
                                    const CalibrationOptions& o) {
  auto reps = run_batch(cfgs, o.jobs);
  for (std::size_t i = 0; i < reps.size(); ++i)
    if (reps[i].value("status", "") != "ok")
      throw std::runtime_error("calibration run " + cfgs[i].algorithm + " on " +
                               cfgs[i].scene_path + " failed: " + reps[i].value("error", "?"));
  return reps;
}

// ---- 1. iPSC/2 against Kurc et al. Table 2 ----------------------------------------------------

struct KurcRun {
  std::string scene, scheme;
};

std::vector<KurcRun> kurc_runs() {
  std::vector<KurcRun> v;
  for (const auto& s : kurc_scenes())
    for (const char* sch : {"pair-rs", "zbuf-exc"})
      v.push_back({s, sch});
  return v;
}

std::vector<nlohmann::json> kurc_reports(const CostTable& cost, const CalibrationOptions& o) {
  TempPlatform plat("ipsc2", cost, kKurcTableNodes);
  std::vector<SimConfig> cfgs;
  for (const auto& r : kurc_runs()) {
    SimConfig c;
    c.machine = plat.path();
    c.nodes = kKurcTableNodes;
    c.algorithm = r.scheme;
    c.scene_path = o.root + "/scenes/kurc/" + r.scene + ".json";
    c.width = c.height = kKurcTableSize;
    c.compare_with_sequential = false; // the images are tested elsewhere; this is a fit
    cfgs.push_back(c);
  }
  return run_all(cfgs, o);
}

// One row of the linear model: the critical node's operations per group (at prior prices) and
// its time not spent computing.
struct PhaseRow {
  std::vector<double> a; // per group
  double wait = 0, time = 0, paper = 0;
  std::string id;
};

std::vector<PhaseRow> kurc_rows(const std::vector<nlohmann::json>& reps, const CostTable& prior,
                                const std::vector<double>& k) {
  const auto runs = kurc_runs();
  std::vector<PhaseRow> rows;
  for (const auto& f : kurc_table2_p16()) {
    std::size_t ri = 0;
    while (runs[ri].scene != f.scene || runs[ri].scheme != f.scheme)
      ++ri;
    const nlohmann::json& rep = reps[ri];
    // The critical node: the longest time in the phase (the paper's figures are the maxima).
    const nlohmann::json* crit = nullptr;
    double best = -1;
    for (const auto& n : rep["per_node"]) {
      const double t = n["phases"].value(f.phase, 0.0);
      if (t > best) {
        best = t;
        crit = &n;
      }
    }
    PhaseRow row;
    row.id = "kurc/p16/" + f.scene + "/" + f.scheme + "/" + f.phase;
    row.time = best;
    row.paper = f.ms * 1e-3;
    const Counters work =
        (*crit)["phase_work"].value(f.phase, nlohmann::json::object()).get<Counters>();
    row.a = group_seconds(prior, cost_groups(), work);
    double cpu = 0;
    for (std::size_t g = 0; g < row.a.size(); ++g)
      cpu += k[g] * row.a[g];
    row.wait = best - cpu;
    rows.push_back(row);
  }
  return rows;
}

bool is_fixed(std::size_t g, const CalibrationOptions& o) {
  const auto& f = o.fixed_groups;
  return std::find(f.begin(), f.end(), cost_groups()[g].name) != f.end();
}

// One NNLS step over the free groups; fixed groups keep their multiplier (their time is moved to
// the right-hand side).
std::vector<double> kurc_step(const std::vector<PhaseRow>& rows, const std::vector<double>& k,
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
  const std::vector<double> x = nnls(A, b);
  std::vector<double> out = k;
  for (std::size_t i = 0; i < free.size(); ++i)
    out[free[i]] = x[i];
  return out;
}

double rms(const std::vector<double>& e) {
  double s = 0;
  for (double x : e)
    s += x * x;
  return e.empty() ? 0 : std::sqrt(s / double(e.size()));
}

// ---- 2. i860 against Charles et al. §6 --------------------------------------------------------

struct CharlesEval {
  double ratio = 0, cost = 0;
  std::vector<double> speedups; // per charles_teapot_speedups() entry
  double seq_s = 0;
};

CharlesEval charles_eval(const CostTable& i386, double ratio, const CalibrationOptions& o) {
  const CostTable i860 = i386.scaled(1.0 / ratio);
  std::vector<std::unique_ptr<TempPlatform>> plats;
  std::vector<SimConfig> cfgs;
  auto add = [&](int nodes, const char* algo) {
    plats.push_back(std::make_unique<TempPlatform>("ipsc860", i860, nodes));
    SimConfig c;
    c.machine = plats.back()->path();
    c.nodes = nodes;
    c.algorithm = algo;
    c.scene_path = o.root + "/scenes/teapot.json";
    c.width = c.height = kCharlesTeapotSize;
    c.compare_with_sequential = false;
    cfgs.push_back(c);
  };
  add(1, "sequential");
  for (const auto& f : charles_teapot_speedups())
    add(f.nodes, "elastic");
  const auto reps = run_all(cfgs, o);
  CharlesEval e;
  e.ratio = ratio;
  e.seq_s = reps[0]["virtual_time_s"].get<double>();
  for (std::size_t i = 0; i < charles_teapot_speedups().size(); ++i) {
    const double s = e.seq_s / reps[i + 1]["virtual_time_s"].get<double>();
    const double paper = charles_teapot_speedups()[i].speedup;
    e.speedups.push_back(s);
    e.cost += std::pow((s - paper) / paper, 2);
  }
  return e;
}

CharlesEval fit_i860(const CostTable& i386, const CalibrationOptions& o, nlohmann::json& log) {
  // Golden-section search on x = log(ratio) over ratios 0.5..200.
  double lo = std::log(0.5), hi = std::log(200.0);
  const double g = (std::sqrt(5.0) - 1) / 2;
  auto eval = [&](double x) {
    CharlesEval e = charles_eval(i386, std::exp(x), o);
    log.push_back({{"ratio", e.ratio}, {"speedups", e.speedups}, {"cost", e.cost}});
    if (o.verbose)
      std::cerr << "calibrate: i860 ratio " << std::setprecision(5) << e.ratio << ": speed-ups "
                << e.speedups[0] << ", " << e.speedups[1] << "\n";
    return e;
  };
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  CharlesEval e1 = eval(x1), e2 = eval(x2);
  while (hi - lo > 1e-4) {
    if (e1.cost <= e2.cost) {
      hi = x2;
      x2 = x1;
      e2 = e1;
      x1 = hi - g * (hi - lo);
      e1 = eval(x1);
    } else {
      lo = x1;
      x1 = x2;
      e1 = e2;
      x2 = lo + g * (hi - lo);
      e2 = eval(x2);
    }
  }
  return e1.cost <= e2.cost ? e1 : e2;
}

} // namespace

nlohmann::json calibrate(const CalibrationOptions& o) {
  const CostTable prior = prior_i386_costs();
  const std::size_t G = cost_groups().size();
  nlohmann::json fit;
  nlohmann::json iters = nlohmann::json::array();

  // 1. 80386 multipliers: fixed-point iteration of the linearised NNLS.
  std::vector<double> k(G, 1.0);
  std::vector<PhaseRow> first, last;
  for (int it = 0;; ++it) {
    const auto reps = kurc_reports(scale_groups(prior, k), o);
    last = kurc_rows(reps, prior, k);
    if (it == 0) first = last;
    std::vector<double> err;
    for (const auto& r : last)
      err.push_back((r.time - r.paper) / r.paper);
    iters.push_back({{"step", it}, {"i386_scale", k}, {"rms_rel_error", rms(err)}});
    if (o.verbose)
      std::cerr << "calibrate: iPSC/2 step " << it << ": rms relative error " << rms(err) << "\n";
    if (it >= o.max_iterations) break;
    const std::vector<double> kn = kurc_step(last, k, o);
    double change = 0;
    for (std::size_t g = 0; g < G; ++g)
      change = std::max(change, std::fabs(kn[g] - k[g]) / std::max(k[g], 1e-9));
    k = kn;
    if (change < 1e-4) {
      // One more run at the settled multipliers, so the residuals are of the final table.
      const auto fin = kurc_reports(scale_groups(prior, k), o);
      last = kurc_rows(fin, prior, k);
      break;
    }
  }
  const CostTable i386 = scale_groups(prior, k);

  // 2. The i860 ratio.
  nlohmann::json clog = nlohmann::json::array();
  const CharlesEval prior_c = charles_eval(prior, 8.0, o);
  const CharlesEval best = fit_i860(i386, o, clog);

  // Targets with the prior and the fitted predictions.
  nlohmann::json targets = nlohmann::json::array();
  std::vector<double> e_prior, e_fit;
  for (std::size_t i = 0; i < last.size(); ++i) {
    const double pr = first[i].time, fi = last[i].time, pa = last[i].paper;
    targets.push_back({{"id", last[i].id},
                       {"machine", "ipsc2"},
                       {"quantity", "phase_ms"},
                       {"paper", pa * 1e3},
                       {"prior", pr * 1e3},
                       {"fitted", fi * 1e3},
                       {"rel_error_prior", (pr - pa) / pa},
                       {"rel_error_fitted", (fi - pa) / pa}});
    e_prior.push_back((pr - pa) / pa);
    e_fit.push_back((fi - pa) / pa);
  }
  for (std::size_t i = 0; i < charles_teapot_speedups().size(); ++i) {
    const auto& f = charles_teapot_speedups()[i];
    const double pr = prior_c.speedups[i], fi = best.speedups[i];
    targets.push_back({{"id", "charles/teapot512/cube/p" + std::to_string(f.nodes)},
                       {"machine", "ipsc860"},
                       {"quantity", "speedup"},
                       {"paper", f.speedup},
                       {"prior", pr},
                       {"fitted", fi},
                       {"rel_error_prior", (pr - f.speedup) / f.speedup},
                       {"rel_error_fitted", (fi - f.speedup) / f.speedup}});
  }

  nlohmann::json groups = nlohmann::json::array();
  for (const auto& g : cost_groups())
    groups.push_back({{"name", g.name}, {"fields", g.fields}});
  auto table_json = [](CostTable t) {
    nlohmann::json j = nlohmann::json::object();
    for (auto& [id, v] : t.fields())
      j[id.substr(5)] = *v;
    return j;
  };
  fit["groups"] = groups;
  fit["i386_scale"] = k;
  fit["i860_ratio"] = best.ratio;
  fit["tables"] = {{"prior_i386", table_json(prior)},
                   {"i386", table_json(i386)},
                   {"i860", table_json(i386.scaled(1.0 / best.ratio))}};
  fit["targets"] = targets;
  fit["iterations"] = {{"ipsc2", iters}, {"i860", clog}};
  fit["rms_rel_error"] = {{"kurc_prior", rms(e_prior)},
                          {"kurc_fitted", rms(e_fit)},
                          {"charles_prior", std::sqrt(prior_c.cost / 2)},
                          {"charles_fitted", std::sqrt(best.cost / 2)}};
  fit["settings"] = {{"ridge", o.ridge},
                     {"fixed_groups", o.fixed_groups},
                     {"kurc_runs", "ipsc2, 16 nodes, cube, 400x400, circuit fidelity"},
                     {"charles_runs", "ipsc860, 1 (sequential), 8 and 16 nodes (elastic, "
                                      "--output device), cube, teapot 512x512, circuit fidelity"}};
  return fit;
}

std::string calibrated_costs_header(const nlohmann::json& fit) {
  std::ostringstream h;
  h << "#pragma once\n"
    << "// Generated by `zcube calibrate --write`: do not edit by hand (results/calibration/ holds "
       "the fit,\n"
    << "// its inputs and residuals). Multipliers of the prior 80386 cost table, one per cost "
       "group in\n"
    << "// cost_groups() order, and the i860's speed over the 80386 (i860 costs = 80386 costs / "
       "ratio).\n"
    << "namespace zc::calibrated {\n"
    << "inline constexpr bool kFitted = true;\n"
    << "inline constexpr double kI386GroupScale[] = {";
  const auto& k = fit["i386_scale"];
  for (std::size_t g = 0; g < k.size(); ++g)
    h << (g ? "," : "") << "\n    " << format_double(k[g].get<double>()) << " /* "
      << fit["groups"][g]["name"].get<std::string>() << " */";
  h << "};\n"
    << "inline constexpr double kI860SpeedRatio = "
    << format_double(fit["i860_ratio"].get<double>()) << ";\n"
    << "} // namespace zc::calibrated\n";
  return h.str();
}

namespace {

std::string fmt(double v, int prec = 4) {
  std::ostringstream s;
  s << std::setprecision(prec) << v;
  return s.str();
}

std::string pct(double v) {
  std::ostringstream s;
  s << std::showpos << std::fixed << std::setprecision(1) << 100 * v << " %";
  return s.str();
}

void write_readme(const nlohmann::json& fit, const std::string& path) {
  std::ofstream md(path);
  md << "# Calibration of the CPU cost tables\n\n"
     << "Written by `zcube calibrate` (src/repro/calibrate.cpp); `zcube calibrate --write` also "
        "rewrites\n`src/machine/calibrated_costs.hpp`, the platform generator's data (then rebuild "
        "and run\n`scripts/gen_platforms.sh`). Inputs: the figures printed in ../shared/seeds "
        "(src/repro/paper_figures.cpp);\nheld-out figures are not used. `fit.json` has every "
        "iteration; `targets.csv` every target.\n\n"
     << "## Method\n\n"
     << "1. **iPSC/2 (16 MHz 80386 + 80387).** The prior table (`prior_i386_costs()`, "
        "src/machine/machine.cpp) is\n   scaled by one multiplier per cost group. Targets: Kurc "
        "et al. Table 2, P = 16, 400x400, PAIR-RS and\n   ZBUF-EXC, six scenes, three phases "
        "(36 figures), simulated as `zcube run --machine ipsc2 --nodes 16\n   --size 400x400 "
        "--algorithm pair-rs|zbuf-exc --scene scenes/kurc/<scene>.json`. A phase's time on its\n"
        "   critical node is linear in the multipliers given the node's waits, t = sum_g k_g A_g + "
        "wait, where A_g\n   is the group's operations that node charged in the phase at prior "
        "prices (the report's\n   `per_node[].phase_work`). Non-negative least squares on the "
        "relative errors, with a weak pull\n   (weight "
     << fit["settings"]["ridge"].get<double>()
     << ") of each multiplier towards 1; then the runs are repeated at the new costs until\n"
        "   the multipliers change by less than 1e-4 (the waits and the critical node move with "
        "the costs).\n"
     << "2. **i860 (iPSC/860 and Volvox: the same 40 MHz part).** The fitted 80386 table divided "
        "by one speed\n   ratio. Targets: the teapot speed-ups of Charles et al. §6 on the "
        "hypercube, 5.6 on 8 nodes and 8.3\n   on 16 (the paper does not give their picture size; "
        "zcube takes 512x512, the size its text says\n   scales best), speed-up = T(sequential, 1 "
        "node) / T(elastic --output device, P nodes). Least squares\n   on the relative errors, "
        "golden-section search over log(ratio).\n\n"
     << "## Result\n\n| cost group | fields | multiplier of the prior |\n|---|---|---|\n";
  for (std::size_t g = 0; g < fit["groups"].size(); ++g) {
    std::string fields;
    for (const auto& f : fit["groups"][g]["fields"])
      fields += (fields.empty() ? "" : ", ") + f.get<std::string>();
    md << "| " << fit["groups"][g]["name"].get<std::string>() << " | " << fields << " | "
       << fmt(fit["i386_scale"][g].get<double>()) << " |\n";
  }
  md << "\ni860 speed ratio over the 80386: **" << fmt(fit["i860_ratio"].get<double>())
     << "**.\n\n| field | prior 80386 (us) | fitted 80386 (us) | fitted i860 (us) |\n"
     << "|---|---|---|---|\n";
  for (const auto& [f, v] : fit["tables"]["i386"].items())
    md << "| " << f << " | " << fmt(fit["tables"]["prior_i386"][f].get<double>() * 1e6) << " | "
       << fmt(v.get<double>() * 1e6) << " | " << fmt(fit["tables"]["i860"][f].get<double>() * 1e6)
       << " |\n";
  const auto& e = fit["rms_rel_error"];
  auto rms = [](double v) { return fmt(100 * v, 3) + " %"; };
  md << "\nRMS relative error: Kurc Table 2 " << rms(e["kurc_prior"].get<double>()) << " (prior) "
     << "-> " << rms(e["kurc_fitted"].get<double>()) << "; Charles speed-ups "
     << rms(e["charles_prior"].get<double>()) << " -> " << rms(e["charles_fitted"].get<double>())
     << ".\n\n## Reading the fit\n\n"
        "- Costs are positive by construction (NNLS), and the i860 machines use the 80386 table "
        "divided by one ratio, so the three machine models stay consistent.\n"
        "- The Kurc 16-node figures and the two Charles speed-ups are what was fitted: their "
        "residuals measure the model's structural fit, not its predictive power. Everything else "
        "in "
        "results/ (Kurc at 8 nodes and the speed-ups, Charles's ring and bone curves, Blazek) is a "
        "prediction.\n"
        "- Per-pixel costs come out high (tens of microseconds a fragment on the 80386): Table 2's "
        "local z-buffer times at the fitted scenes' fragment counts (Table 1) demand it.\n"
        "- `packing` (bytes copied into messages) is exercised by few targets (PAIR messages "
        "gathered from several runs of scanlines) and absorbs the per-pixel handling of those "
        "messages; `zcube calibrate --fix packing` keeps it at the prior and shows the price "
        "(a larger error on the PAIR-RS merging phase).\n"
        "- The i860 ratio is the one free parameter for two figures: both are matched within a few "
        "per cent, which supports the model's balance of computation and communication on the "
        "iPSC/860.\n"
     << "\n## Every target\n\n| target | paper | prior | fitted | error (prior) | error "
        "(fitted) |\n|---|---|---|---|---|---|\n";
  for (const auto& t : fit["targets"])
    md << "| " << t["id"].get<std::string>() << " | " << fmt(t["paper"].get<double>()) << " | "
       << fmt(t["prior"].get<double>()) << " | " << fmt(t["fitted"].get<double>()) << " | "
       << pct(t["rel_error_prior"].get<double>()) << " | "
       << pct(t["rel_error_fitted"].get<double>()) << " |\n";
}

} // namespace

void write_calibration_results(const nlohmann::json& fit, const std::string& dir) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/fit.json") << fit.dump(2) << "\n";
  std::ofstream csv(dir + "/targets.csv");
  csv << "target,machine,quantity,paper,prior,fitted,rel_error_prior,rel_error_fitted\n";
  auto num = [](double v) {
    std::ostringstream s;
    s << std::setprecision(6) << v;
    return s.str();
  };
  for (const auto& t : fit["targets"])
    csv << t["id"].get<std::string>() << "," << t["machine"].get<std::string>() << ","
        << t["quantity"].get<std::string>() << "," << num(t["paper"]) << "," << num(t["prior"])
        << "," << num(t["fitted"]) << "," << num(t["rel_error_prior"]) << ","
        << num(t["rel_error_fitted"]) << "\n";
  write_readme(fit, dir + "/README.md");
}

} // namespace zc
