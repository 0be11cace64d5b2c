// Helpers shared by the reproduction plans.
#include "repro/reproduce.hpp"

#include <cmath>

#include "machine/uncertainty.hpp"

namespace zc {

RunConfig repro_config(const std::string& machine, int nodes, const std::string& algorithm,
                       const std::string& scene, int size) {
  RunConfig c;
  c.machine = machine;
  c.nodes = nodes;
  c.algorithm = algorithm;
  c.scene_path = scene;
  c.width = c.height = size;
  return c;
}

bool ok(const nlohmann::json& r) {
  return r.value("status", "") == "ok";
}

bool out_of_memory(const nlohmann::json& r) {
  return r.value("status", "") == "out_of_memory";
}

double timed_s(const nlohmann::json& r) {
  return r.contains("timed_s") ? r["timed_s"].get<double>() : r.value("virtual_time_s", 0.0);
}

double whole_run_s(const nlohmann::json& r) {
  return r.value("virtual_time_s", 0.0);
}

std::string status_of(const nlohmann::json& r) {
  const std::string s = r.value("status", "");
  return s.empty() ? "error" : s;
}

void with_bands(PaperPlan& plan) {
  for (auto& p : plan.points)
    p.cfg.band_draws = kReproduceDraws;
}

namespace {
std::vector<double> draw_values(const nlohmann::json& v) {
  std::vector<double> out;
  for (const auto& x : v)
    out.push_back(x.is_number() ? x.get<double>() : std::nan(""));
  return out;
}
} // namespace

std::vector<double> band_timed_s(const nlohmann::json& r) {
  if (!r.contains("bands") || !r["bands"].contains("values")) return {};
  const auto& v = r["bands"]["values"];
  return draw_values(r.contains("timed_s") && v.contains("timed_s") ? v["timed_s"]
                                                                    : v["virtual_time_s"]);
}

std::vector<double> band_phases_s(const nlohmann::json& r, const std::vector<std::string>& phases) {
  if (!r.contains("bands") || !r["bands"].contains("values")) return {};
  const auto& v = r["bands"]["values"];
  std::vector<double> sum(v["virtual_time_s"].size(), 0.0);
  for (const auto& ph : phases) {
    if (!v.contains("phases") || !v["phases"].contains(ph)) continue;
    const auto x = draw_values(v["phases"][ph]);
    for (std::size_t d = 0; d < sum.size() && d < x.size(); ++d)
      sum[d] += x[d];
  }
  return sum;
}

std::pair<double, double> ratio_band(const std::vector<double>& num,
                                     const std::vector<double>& den) {
  std::vector<double> r;
  for (std::size_t d = 0; d < num.size() && d < den.size(); ++d)
    if (std::isfinite(num[d]) && std::isfinite(den[d]) && den[d] > 0) r.push_back(num[d] / den[d]);
  if (r.empty()) return {std::nan(""), std::nan("")};
  return {quantile(r, 0.05), quantile(r, 0.95)};
}

std::string gantt_markdown(const std::vector<GanttChart>& charts) {
  std::string md = "\n## Space-time diagrams\n\n"
                   "One row per node (and the host computer): the phase above, what the node does "
                   "below (compute, send, wait, idle), messages as lines from sender to receiver, "
                   "and the nodes computing, sending and waiting beneath (`zcube run --gantt`, "
                   "scripts/plot_gantt.py).\n\n";
  for (const auto& g : charts)
    ((((md += "- ") += g.caption) += ": [") += g.file) += "](" + g.file + ")\n";
  return md;
}

} // namespace zc
