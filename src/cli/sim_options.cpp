#include "cli/sim_options.hpp"

#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <simgrid/s4u/Engine.hpp>

#include "machine/platform_xml.hpp"
#include "repro/simulate.hpp"
#include "run/run_flags.hpp"
#include "sim/simgrid_args.hpp"
#include "util/error.hpp"

namespace zc::cli {

void SimFlags::add_to(CLI::App& app) {
  app.add_option("--machine", machine, "ipsc2, ipsc860, volvox, or a platform .xml")
      ->capture_default_str();
  nodes_option =
      app.add_option("--nodes", nodes,
                     "simulated nodes (a power of two on a cube; a platform .xml states its own)")
          ->capture_default_str();
  topology_option =
      app.add_option("--topology", topology, "cube or ring (a platform .xml states its own)")
          ->capture_default_str();
  app.add_option("--fidelity", fidelity, "analytic, flow or circuit")->capture_default_str();
  app.add_option("--latency", latency, "what-if: message start-up (e.g. 275us)");
  app.add_option("--bandwidth", bandwidth, "what-if: channel bandwidth (e.g. 2.8MBps)");
  app.add_option("--per-hop", per_hop, "what-if: per-hop cost (e.g. 10us)");
  app.add_option("--host-latency", host_latency,
                 "what-if: host (srm) link start-up to node 0 (e.g. 1ms)");
  app.add_option("--host-bandwidth", host_bandwidth,
                 "what-if: host (srm) link bandwidth (e.g. 1MBps)");
  app.add_option("--cpu-scale", cpu_scale, "what-if: multiply every CPU cost (0.25 = 4x faster)");
  app.add_option("--memory", memory, "what-if: node memory (e.g. 16MiB)");
  app.add_option("--cost-scale", cost_scale, "multiply every cost, CPU and network");
  app.add_option("--cfg", cfg,
                 "a SimGrid setting name:value, passed to SimGrid after zcube's own (e.g. "
                 "network/model:LV08 with --fidelity flow; --help-cfg lists them); repeatable");
  app.add_option("--log", log,
                 "a SimGrid log setting (e.g. root.thres:info; zcube sets root.thres:critical); "
                 "repeatable");
  app.add_flag_callback("--help-cfg", print_simgrid_settings,
                        "list SimGrid's settings (--cfg names, values, defaults) and exit");
  app.footer(whatif_help());
}

std::string whatif_help() {
  std::ostringstream s;
  s << std::setprecision(4)
    << "What-if units (SimGrid's; `zcube units` lists them all), required on every flag:\n"
       "  times  s ms us ns (also m h d w)    --latency, --per-hop, --host-latency: 0 .. 1 h\n"
       "  rates  Bps kBps MBps GBps KiBps MiBps bps kbps Mbps    --bandwidth, --host-bandwidth: "
       ">= 1 Bps\n"
       "  sizes  B kB MB KiB MiB GiB    --memory: > 0\n"
       "  --cpu-scale 1e-3 .. 1e3, --cost-scale 1e-6 .. 1e6 (plain numbers)\n"
       "Each machine's own figures (docs/machines.md has their sources):\n"
       "  machine   start-up short/long  bandwidth  per hop  host link        memory  clock    "
       "switching\n";
  for (const auto& name : machine_names()) {
    const MachineSpec& m = machine_spec(name);
    const NetworkParams& n = m.net;
    char line[200];
    std::snprintf(line, sizeof line,
                  "  %-8s  %5.4g/%-5.4g us   %5.4g MBps  %4.3g us  %5.4g us %4.3g MBps  %2g MiB  "
                  "%3g MHz  %s\n",
                  name.c_str(), n.startup_short_s * 1e6, n.startup_long_s * 1e6,
                  1e-6 / n.per_byte_s, n.per_hop_s * 1e6, n.host_startup_s * 1e6,
                  1e-6 / n.host_per_byte_s, m.memory_bytes / 1048576, cpu_clock_hz(m) / 1e6,
                  n.switching == Switching::Circuit ? "circuit" : "store-and-forward");
    s << line;
  }
  return s.str();
}

void print_simgrid_settings() {
  // SimGrid prints its settings and ends the process itself on --cfg-help.
  std::vector<std::string> args = {"zcube", "--cfg-help"};
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  int argc = int(argv.size());
  simgrid::s4u::Engine e(&argc, argv.data());
  std::exit(0);
}

namespace {

// A --cfg the fidelity never reads is refused rather than printed and ignored: only the flow
// fidelity lets SimGrid's network model time messages (the others charge them in zcube,
// platforms/README.md), and zcube runs no SMPI program.
void check_cfg_is_read(const std::string& name, const std::string& value,
                       const std::string& fidelity) {
  if (name.rfind("smpi/", 0) == 0)
    throw UsageError("--cfg " + name + ":" + value +
                     ": zcube runs no SMPI program, so SMPI's settings change nothing");
  // fidelity "": the runs' own, some of which may be flow (a batch command notes it).
  if (name.rfind("network/", 0) == 0 && !fidelity.empty() && fidelity != "flow")
    throw UsageError("--cfg " + name + ":" + value + ": the " + fidelity +
                     " fidelity times messages itself; SimGrid's network settings take effect "
                     "under --fidelity flow only");
}

} // namespace

std::vector<std::string> simgrid_args_of(const std::vector<std::string>& cfg,
                                         const std::vector<std::string>& log,
                                         const std::string& fidelity) {
  std::vector<std::string> a;
  for (const auto& c : cfg) {
    const auto colon = c.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == c.size())
      throw UsageError("--cfg '" + c + "': expected name:value (e.g. network/model:LV08)");
    check_cfg_is_read(c.substr(0, colon), c.substr(colon + 1), fidelity);
    a.push_back("--cfg=" + c);
  }
  for (const auto& l : log) {
    if (l.find(':') == std::string::npos && l.find('=') == std::string::npos)
      throw UsageError("--log '" + l + "': expected category.setting:value (e.g. root.thres:info)");
    a.push_back("--log=" + l);
  }
  return a;
}

std::vector<std::string> SimFlags::simgrid_args() const {
  return simgrid_args_of(cfg, log, fidelity);
}

void BatchSimGridFlags::add_to(CLI::App& app) {
  app.add_option("--cfg", cfg,
                 "a SimGrid setting name:value for every simulation, after zcube's own (network/* "
                 "changes only runs under the flow fidelity; --help-cfg lists them); repeatable");
  app.add_option("--log", log,
                 "a SimGrid log setting for every simulation (e.g. "
                 "root.thres:warning); repeatable");
  app.add_flag_callback("--help-cfg", print_simgrid_settings,
                        "list SimGrid's settings (--cfg names, values, defaults) and exit");
}

void BatchSimGridFlags::apply() const {
  const auto args = simgrid_args_of(cfg, log, "");
  check_simgrid_args(args);
  for (const auto& c : cfg)
    if (c.rfind("network/", 0) == 0)
      std::cerr << "zcube: note: --cfg " << c
                << " changes only the runs under the flow fidelity (the others time messages in "
                   "zcube)\n";
  set_batch_simgrid_args(args);
}

std::map<std::string, std::string> SimFlags::flags() const {
  std::map<std::string, std::string> m = {{"machine", machine}, {"fidelity", fidelity}};
  // A platform .xml states its own node count unless --nodes is given, and its own topology.
  const bool xml = machine.ends_with(".xml");
  if (!xml || (nodes_option && nodes_option->count() > 0)) m["nodes"] = std::to_string(nodes);
  if (!xml || (topology_option && topology_option->count() > 0)) m["topology"] = topology;
  const std::pair<const char*, const std::string*> text[] = {{"latency", &latency},
                                                             {"bandwidth", &bandwidth},
                                                             {"per-hop", &per_hop},
                                                             {"host-latency", &host_latency},
                                                             {"host-bandwidth", &host_bandwidth},
                                                             {"cpu-scale", &cpu_scale},
                                                             {"memory", &memory},
                                                             {"cost-scale", &cost_scale}};
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
  cfg.simgrid_args = simgrid_args();
  check_simgrid_args(cfg.simgrid_args);
}

std::string describe_overrides(const SimConfig& c) {
  const Overrides& o = c.overrides;
  std::ostringstream s;
  s << std::setprecision(6);
  if (o.latency_s) s << "what-if: --latency " << *o.latency_s * 1e6 << " us (message start-up)\n";
  if (o.bandwidth_Bps)
    s << "what-if: --bandwidth " << *o.bandwidth_Bps / 1e6 << " MB/s (channel bandwidth)\n";
  if (o.per_hop_s) s << "what-if: --per-hop " << *o.per_hop_s * 1e6 << " us\n";
  if (o.host_latency_s)
    s << "what-if: --host-latency " << *o.host_latency_s * 1e6 << " us (host link start-up)\n";
  if (o.host_bandwidth_Bps)
    s << "what-if: --host-bandwidth " << *o.host_bandwidth_Bps / 1e6
      << " MB/s (host link bandwidth)\n";
  if (o.cpu_scale) s << "what-if: --cpu-scale " << *o.cpu_scale << " (every CPU cost)\n";
  if (o.memory_bytes)
    s << "what-if: --memory " << *o.memory_bytes / 1048576 << " MiB (node memory)\n";
  if (o.cost_scale) s << "what-if: --cost-scale " << *o.cost_scale << " (every cost)\n";
  for (const auto& a : c.simgrid_args)
    s << "SimGrid: " << a << "\n";
  return s.str();
}

} // namespace zc::cli
