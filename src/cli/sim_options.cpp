#include "cli/sim_options.hpp"

#include "sim/run_flags.hpp"

namespace zc::cli {

void SimFlags::add_to(CLI::App& app) {
  app.add_option("--machine", machine, "ipsc2, ipsc860, volvox, or a platform .xml")
      ->capture_default_str();
  nodes_option =
      app.add_option("--nodes", nodes,
                     "simulated nodes (a power of two on a cube; a platform .xml states its own)")
          ->capture_default_str();
  app.add_option("--topology", topology, "cube or ring")->capture_default_str();
  app.add_option("--fidelity", fidelity, "analytic, flow or circuit")->capture_default_str();
  app.add_option("--latency", latency, "what-if: message start-up (e.g. 275us)");
  app.add_option("--bandwidth", bandwidth, "what-if: channel bandwidth (e.g. 2.8MBps)");
  app.add_option("--per-hop", per_hop, "what-if: per-hop cost (e.g. 10us)");
  app.add_option("--cpu-scale", cpu_scale, "what-if: multiply every CPU cost (0.25 = 4x faster)");
  app.add_option("--memory", memory, "what-if: node memory (e.g. 16MiB)");
  app.add_option("--cost-scale", cost_scale, "multiply every cost, CPU and network");
}

std::map<std::string, std::string> SimFlags::flags() const {
  std::map<std::string, std::string> m = {
      {"machine", machine}, {"topology", topology}, {"fidelity", fidelity}};
  // A platform .xml states its own node count unless --nodes is given.
  if (!machine.ends_with(".xml") || (nodes_option && nodes_option->count() > 0))
    m["nodes"] = std::to_string(nodes);
  const std::pair<const char*, const std::string*> text[] = {
      {"latency", &latency},     {"bandwidth", &bandwidth}, {"per-hop", &per_hop},
      {"cpu-scale", &cpu_scale}, {"memory", &memory},       {"cost-scale", &cost_scale}};
  for (const auto& [k, v] : text)
    if (!v->empty()) m[k] = *v;
  return m;
}

void SimFlags::apply(SimConfig& cfg) const {
  const SimConfig c = config_from_flags(flags(), cfg.scene_path);
  cfg.machine = c.machine;
  cfg.nodes = c.nodes;
  cfg.topology = c.topology;
  cfg.fidelity = c.fidelity;
  cfg.overrides = c.overrides;
}

} // namespace zc::cli
