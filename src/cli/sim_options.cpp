#include "cli/sim_options.hpp"

#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <simgrid/s4u/Engine.hpp>

#include "cli/paths.hpp"
#include "machine/platform_xml.hpp"
#include "repro/simulate.hpp"
#include "run/run_flags.hpp"
#include "sim/simgrid_args.hpp"
#include "util/error.hpp"

namespace zc::cli {

void add_run_flag_options(CLI::App& app, std::map<std::string, std::string>& values,
                          const std::function<bool(const RunFlag&)>& want, bool lists) {
  for (const auto& f : run_flags()) {
    if (!want(f)) continue;
    std::string help = lists ? "comma-separated values of zcube run --" + f.name + ": " : "";
    help += f.help;
    if (!f.default_text.empty()) help += " [" + f.default_text + "]";
    app.add_option("--" + f.name, values[f.name], help)->type_name(f.value_form);
  }
}

std::map<std::string, std::string> given_flags(const std::map<std::string, std::string>& values) {
  std::map<std::string, std::string> m;
  for (const auto& [k, v] : values)
    if (!v.empty()) m[k] = k == "machine" || k == "scene" ? data_file(v) : v;
  return m;
}

void SimFlags::add_to(CLI::App& app) {
  add_run_flag_options(app, values, [](const RunFlag& f) {
    return f.group == RunFlag::Group::WhatIf || f.name == "machine" || f.name == "nodes" ||
           f.name == "topology" || f.name == "fidelity";
  });
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
    << "What-ifs: an absolute figure with its unit (SimGrid's; `zcube units` lists them), or xK, "
       "K times the machine's own figure (--latency x0.1: each message protocol's start-up a "
       "tenth):\n";
  for (const auto& w : what_if_specs())
    s << "  --" << std::left << std::setw(15) << w.flag << std::setw(16) << w.example << w.bounds
      << "\n";
  s << "Each machine's own figures (docs/machines.md has their sources):\n"
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
  const auto f = values.find("fidelity");
  return simgrid_args_of(cfg, log, f == values.end() || f->second.empty() ? "circuit" : f->second);
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
  auto m = given_flags(values);
  // A platform .xml states its own node count and topology: a command's default does not apply.
  const bool xml = m.count("machine") && is_platform_file(m.at("machine"));
  for (const auto& [k, v] : defaults)
    if (!xml) m.emplace(k, v);
  return m;
}

void SimFlags::apply(RunConfig& cfg) const {
  const RunConfig c = config_from_flags(flags(), cfg.scene_path);
  cfg.machine = c.machine;
  cfg.nodes = c.nodes;
  cfg.topology = c.topology;
  cfg.fidelity = c.fidelity;
  cfg.what_ifs = c.what_ifs;
  cfg.simgrid_args = simgrid_args();
  check_simgrid_args(cfg.simgrid_args);
}

std::string describe_overrides(const RunConfig& c) {
  std::ostringstream s;
  for (const auto& [spec, v] : c.what_ifs.in_order())
    s << "what-if: --" << spec->flag << " " << what_if_text(*spec, v) << " (" << spec->meaning
      << ")\n";
  for (const auto& a : c.simgrid_args)
    s << "SimGrid: " << a << "\n";
  return s.str();
}

} // namespace zc::cli
