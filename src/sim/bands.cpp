#include "sim/bands.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "machine/machine.hpp"
#include "run/batch.hpp"
#include "sim/platform_load.hpp"
#include "sim/replay.hpp"
#include "sim/retime.hpp"
#include "sim/simulation.hpp"

namespace zc {

namespace {

// The figures a band is given for, from a report or a retimed run.
struct Figures {
  bool ok = false;
  double virtual_time_s = 0, timed_s = -1;
  std::map<std::string, double> phases; // max_s
};

Figures figures_of(const RetimedRun& r) {
  Figures f;
  f.ok = r.status == RetimedRun::Status::Ok;
  f.virtual_time_s = r.virtual_time_s;
  f.timed_s = r.timed_s;
  for (std::size_t i = 0; i < r.phase_names.size(); ++i)
    f.phases[r.phase_names[i]] = r.phase_max_s[i];
  return f;
}

Figures figures_of(const nlohmann::json& j) {
  Figures f;
  f.ok = j.value("status", "") == "ok";
  if (!f.ok) return f;
  f.virtual_time_s = j.at("virtual_time_s").get<double>();
  f.timed_s = j.value("timed_s", -1.0);
  for (const auto& p : j.at("phases"))
    f.phases[p.at("name").get<std::string>()] = p.at("max_s").get<double>();
  return f;
}

// The same of a report before it is written.
Figures figures_of(const Report& r) {
  Figures f;
  f.ok = r.ok();
  if (!f.ok) return f;
  f.virtual_time_s = r.virtual_time_s;
  f.timed_s = timed_region_s(r).value_or(-1.0);
  for (const NodeRecord& rec : r.records)
    for (const auto& [name, t] : rec.phase_totals) {
      double& m = f.phases[name]; // 0 at first, as the report's max_s starts
      m = std::max(m, t);
    }
  return f;
}

// The largest relative difference between two sets of figures (the retimer against the run).
double disagreement(const Figures& a, const Figures& b) {
  const auto rel = [](double x, double y) {
    return std::abs(x - y) / std::max({std::abs(x), std::abs(y), 1e-300});
  };
  double d = rel(a.virtual_time_s, b.virtual_time_s);
  if ((a.timed_s < 0) != (b.timed_s < 0)) return 1;
  if (a.timed_s >= 0) d = std::max(d, rel(a.timed_s, b.timed_s));
  if (a.phases.size() != b.phases.size()) return 1;
  for (const auto& [name, v] : a.phases) {
    auto it = b.phases.find(name);
    if (it == b.phases.end()) return 1;
    d = std::max(d, rel(v, it->second));
  }
  return d;
}

RetimeMachine retime_machine(const PlatformModel& pm, const RunConfig& cfg) {
  RetimeMachine m;
  m.nodes = pm.nodes;
  m.topology = pm.topology;
  m.fidelity = cfg.fidelity;
  m.net = pm.net;
  m.cost = pm.cost;
  m.memory = pm.memory;
  m.os_resident = pm.os_resident;
  m.precision = 1e-12 * cfg.what_ifs.cost_scale();
  return m;
}

nlohmann::json quantiles(const std::vector<double>& v) {
  return {{"p05", quantile(v, 0.05)}, {"p50", quantile(v, 0.5)}, {"p95", quantile(v, 0.95)}};
}

// The finite values of v (a failed draw's are NaN).
std::vector<double> finite(const std::vector<double>& v) {
  std::vector<double> f;
  for (double x : v)
    if (std::isfinite(x)) f.push_back(x);
  return f;
}

// Writes the band of every figure from the draws' figures into the report. `values` keep one
// entry a draw, in draw order, null where the draw failed, so that a study pairs its runs' draws.
void write_bands(Report& report, const std::vector<Figures>& draws, nlohmann::json b) {
  const double none = std::nan("");
  std::vector<double> vt, ts;
  std::map<std::string, std::vector<double>> ph;
  int failed = 0;
  const std::vector<std::string> phases = phase_names(report.records);
  for (const auto& name : phases)
    ph[name];
  for (const Figures& f : draws) {
    failed += !f.ok;
    vt.push_back(f.ok ? f.virtual_time_s : none);
    ts.push_back(f.ok && f.timed_s >= 0 ? f.timed_s : none);
    for (auto& [n, v] : ph) {
      const auto it = f.phases.find(n);
      v.push_back(f.ok && it != f.phases.end() ? it->second : none);
    }
  }
  b["failed_draws"] = failed;
  if (finite(vt).empty()) {
    b["method"] = "unavailable";
    b["why"] = "no draw ran to its end";
    report.bands = std::move(b);
    return;
  }
  b["virtual_time_s"] = quantiles(finite(vt));
  b["values"] = {{"virtual_time_s", vt}};
  if (!finite(ts).empty()) {
    b["timed_s"] = quantiles(finite(ts));
    b["values"]["timed_s"] = ts;
  }
  for (const auto& name : phases) {
    const auto& v = ph.at(name);
    if (finite(v).empty()) continue;
    report.phase_bands[name] = quantiles(finite(v));
    b["values"]["phases"][name] = v;
  }
  report.bands = std::move(b);
}

nlohmann::json band_header(const RunConfig& cfg, const BandsRequest& req,
                           const std::string& machine, const char* method) {
  return {{"draws", req.draws},
          {"seed", req.seed},
          {"method", method},
          {"model", "docs/uncertainty.md"},
          {"machine_ranges", uncertainty_spec(machine).known},
          {"fidelity", fidelity_name(cfg.fidelity)}};
}

// Elasticities of every figure against every model parameter, by central differences of the
// retimed run (nominal structural factors).
nlohmann::json sensitivity(const CallTrace& t, const RetimeMachine& m, double step) {
  nlohmann::json s = {{"step", step}, {"method", "retimed"}};
  const auto& params = model_parameters();
  for (std::size_t p = 0; p < params.size(); ++p) {
    const Figures up = figures_of(retime(t, m, scaled_parameter(p, std::exp(step))));
    const Figures down = figures_of(retime(t, m, scaled_parameter(p, std::exp(-step))));
    if (!up.ok || !down.ok) continue;
    const auto e = [step](double a, double b) {
      return a > 0 && b > 0 ? (std::log(a) - std::log(b)) / (2 * step) : 0.0;
    };
    s["virtual_time_s"][params[p]] = e(up.virtual_time_s, down.virtual_time_s);
    if (up.timed_s >= 0) s["timed_s"][params[p]] = e(up.timed_s, down.timed_s);
    for (const auto& [name, v] : up.phases)
      s["phases"][name][params[p]] = e(v, down.phases.at(name));
  }
  return s;
}

} // namespace

void mark_unavailable(Report& report, const BandsRequest& req, const std::string& why) {
  if (req.draws > 0 && report.bands.is_null())
    report.bands = {{"method", "unavailable"}, {"why", why}, {"draws", req.draws}};
  if (req.sensitivity && report.sensitivity.is_null())
    report.sensitivity = {{"method", "unavailable"}, {"why", why}};
}

std::string add_bands(Report& report, const CallTrace& trace, const PlatformModel& pm,
                      const RunConfig& cfg, const BandsRequest& req) {
  const RetimeMachine m = retime_machine(pm, cfg);
  std::string why = retimable(m);
  // The retimer must give the simulated run's own figures before it prices anything else.
  const double agreement =
      why.empty() ? disagreement(figures_of(retime(trace, m, ModelDraw{})), figures_of(report))
                  : 0.0;
  if (why.empty() && !(agreement <= 1e-9))
    why = "the retimed run differs from the simulation by " + std::to_string(agreement) +
          " (relative)";
  if (!why.empty()) {
    mark_unavailable(report, req, why);
    return why;
  }
  if (req.draws > 0) {
    std::vector<Figures> draws;
    int diverged = 0, reordered = 0;
    const UncertaintySpec& spec = cfg.band_spec ? *cfg.band_spec : uncertainty_spec(pm.machine);
    for (const ModelDraw& d : model_draws(spec, req.draws, req.seed)) {
      const RetimedRun r = retime(trace, m, d);
      diverged += r.status == RetimedRun::Status::Diverged;
      reordered += r.reordered_receives > 0;
      draws.push_back(figures_of(r));
    }
    nlohmann::json b = band_header(cfg, req, pm.machine, "retimed");
    b["agreement_rel"] = agreement;
    b["diverged_draws"] = diverged;
    b["reordered_draws"] = reordered;
    write_bands(report, draws, std::move(b));
  }
  if (req.sensitivity) report.sensitivity = sensitivity(trace, m, req.step);
  return "";
}

namespace {

// Why a run of cfg cannot be retimed, as far as the configuration says before it runs ("" when
// it can; a platform file's links are known only once it is loaded).
std::string not_retimable(const RunConfig& cfg) {
  NetworkParams n;
  if (!is_platform_file(cfg.machine)) {
    MachineFigures f = machine_figures(machine_spec(cfg.machine), cfg.nodes);
    apply_what_ifs(cfg.what_ifs, f);
    n = f.net;
  }
  return retimable(cfg.fidelity, n);
}

// Every draw a simulation of its own, in child processes: the first records, the others replay.
std::vector<Figures> simulated_draws(const RunConfig& cfg, const BandsRequest& req,
                                     const std::string& machine) {
  std::vector<RunConfig> points;
  for (const ModelDraw& d : model_draws(machine, req.draws, req.seed)) {
    RunConfig c = cfg;
    c.draw = std::make_shared<const ModelDraw>(d);
    c.compare_with_sequential = false;
    c.timeline = false;
    points.push_back(std::move(c));
  }
  ReplayRunner runner{[](const RunConfig&) { return std::string("draws"); },
                      [](const RunConfig& c, std::vector<std::uint8_t>* trace) {
                        std::shared_ptr<CallTrace> t;
                        RunResult r = record_simulation(c, nullptr, t);
                        if (t && trace) *trace = t->serialize();
                        return report_json(r.report);
                      },
                      [](const RunConfig& c,
                         const std::vector<std::uint8_t>& bytes) -> std::optional<nlohmann::json> {
                        auto t = std::make_shared<const CallTrace>(CallTrace::parse(bytes));
                        auto r = replay_simulation(c, nullptr, t);
                        if (!r) return std::nullopt;
                        return report_json(r->report);
                      }};
  TraceStore traces;
  std::vector<Figures> out;
  for (const auto& j : run_batch_replaying(points, default_jobs(), runner, traces))
    out.push_back(figures_of(j));
  return out;
}

} // namespace

RunResult run_with_bands(const RunConfig& cfg, const BandsRequest& req, const Scene* preloaded) {
  // Draws that need simulations of their own run before this process has an engine.
  const std::string simulated_why = not_retimable(cfg);
  std::vector<Figures> simulated;
  if (!simulated_why.empty() && req.draws > 0)
    simulated = simulated_draws(cfg, req, is_platform_file(cfg.machine) ? "" : cfg.machine);
  std::shared_ptr<CallTrace> trace;
  PlatformModel pm;
  RunResult r = record_simulation(cfg, preloaded, trace, &pm);
  if (!r.ok()) return r;
  if (!simulated_why.empty() && req.draws > 0) {
    nlohmann::json b = band_header(cfg, req, pm.machine, "simulated");
    b["why_simulated"] = simulated_why;
    write_bands(r.report, simulated, std::move(b));
  }
  if (!simulated_why.empty())
    mark_unavailable(r.report, req, simulated_why);
  else if (!trace)
    mark_unavailable(r.report, req, "the run read the clock: its calls may depend on the times");
  else
    add_bands(r.report, *trace, pm, cfg, req);
  return r;
}

} // namespace zc
