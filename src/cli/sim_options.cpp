#include "cli/sim_options.hpp"

#include "machine/units.hpp"
#include "util/error.hpp"

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

static double positive_number(const std::string& s, const std::string& flag) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end || !(v > 0) || v == HUGE_VAL)
    throw UsageError(flag + " '" + s + "': expected a positive number");
  return v;
}

void SimFlags::apply(SimConfig& cfg) const {
  cfg.machine = machine;
  cfg.nodes = nodes;
  cfg.topology = parse_topology(topology);
  cfg.fidelity = parse_fidelity(fidelity);
  if (!machine.ends_with(".xml"))
    check_node_count(cfg.topology, nodes);
  else if (nodes_option && nodes_option->count() == 0)
    cfg.nodes = 0; // take the file's node count (zcube.nodes)
  if (!latency.empty()) cfg.overrides.latency_s = parse_time(latency, "--latency");
  if (!bandwidth.empty()) cfg.overrides.bandwidth_Bps = parse_bandwidth(bandwidth, "--bandwidth");
  if (!per_hop.empty()) cfg.overrides.per_hop_s = parse_time(per_hop, "--per-hop");
  if (!cpu_scale.empty()) cfg.overrides.cpu_scale = positive_number(cpu_scale, "--cpu-scale");
  if (!memory.empty()) cfg.overrides.memory_bytes = parse_bytes(memory, "--memory");
  if (!cost_scale.empty()) cfg.overrides.cost_scale = positive_number(cost_scale, "--cost-scale");
}

} // namespace zc::cli
