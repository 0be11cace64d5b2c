// Helpers shared by the reproduction plans.
#include "repro/reproduce.hpp"

namespace zc {

SimConfig repro_config(const std::string& machine, int nodes, const std::string& algorithm,
                       const std::string& scene, int size) {
  SimConfig c;
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

double virtual_s(const nlohmann::json& r) {
  // The paper's timed region when the algorithm marks one (docs/papers.md), else the whole run.
  return r.contains("timed_s") ? r["timed_s"].get<double>() : r.value("virtual_time_s", 0.0);
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
