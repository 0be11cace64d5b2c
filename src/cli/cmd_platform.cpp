// zcube platform: writes the SimGrid platform file of a machine model, with what-if figures a user
// can keep and run (`zcube run --machine that.xml`).
#include <iostream>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/sim_options.hpp"
#include "machine/platform_xml.hpp"
#include "machine/units.hpp"
#include "run/run_flags.hpp"
#include "sim/simulation.hpp"
#include "util/output_file.hpp"
#include "util/stdout_result.hpp"

namespace zc::cli {

namespace {

// The machine with the what-ifs in force, written as the figures SimGrid reads.
MachineSpec edited(MachineSpec spec, const Overrides& o, const std::string& command) {
  if (o.latency_s) spec.net.startup_short_s = spec.net.startup_long_s = *o.latency_s;
  const double one_way_per_byte = spec.net.per_byte_s;
  if (o.bandwidth_Bps) spec.net.per_byte_s = 1.0 / *o.bandwidth_Bps;
  // The two-way total keeps its ratio to the channel rate, as the --bandwidth flag scales it on a
  // run (sim/platform_load.cpp, apply_overrides): the Volvox keeps its duplex links.
  if (spec.net.both_ways_Bps > 0 && spec.net.per_byte_s != one_way_per_byte)
    spec.net.both_ways_Bps *= one_way_per_byte / spec.net.per_byte_s;
  if (o.per_hop_s) spec.net.per_hop_s = *o.per_hop_s;
  if (o.host_latency_s) spec.net.host_startup_s = *o.host_latency_s;
  if (o.host_bandwidth_Bps) spec.net.host_per_byte_s = 1.0 / *o.host_bandwidth_Bps;
  if (o.memory_bytes) spec.memory_bytes = *o.memory_bytes;
  const double lowest = spec.net.per_hop_s + kSmpiEnvelopeBytes * spec.net.per_byte_s;
  const double startup = std::min(spec.net.startup_short_s, spec.net.startup_long_s);
  if (startup < lowest) {
    // Name the flag that moved the figure past the other: the start-up given, else the channel's.
    const std::string need = format_double(lowest * 1e6) + " us";
    if (o.latency_s)
      throw UsageError("--latency must be at least the per-hop cost plus 16 bytes at the channel "
                       "rate (" +
                       need + "): SMPI's receive overhead would be < 0");
    throw UsageError(std::string(o.bandwidth_Bps ? "--bandwidth" : "--per-hop") +
                     ": the per-hop cost plus 16 bytes at the channel rate (" + need +
                     ") exceed the start-up (" + format_double(startup * 1e6) +
                     " us), so SMPI's receive overhead would be < 0; give a --latency of at "
                     "least " +
                     need);
  }
  spec.generated_by = "`" + command + "`";
  return spec;
}

} // namespace

static int cmd_platform(std::vector<std::string> args) {
  CLI::App app{"Write the SimGrid platform file of a machine model (what-ifs included)",
               "zcube platform"};
  std::map<std::string, std::string> flags = {
      {"machine", "ipsc2"}, {"nodes", "1"}, {"topology", "cube"}};
  std::string out;
  app.add_option("--machine", flags["machine"], "ipsc2, ipsc860 or volvox")->capture_default_str();
  app.add_option("--nodes", flags["nodes"], "number of nodes (cube: a power of two; up to 1024)")
      ->type_name("INT")
      ->capture_default_str();
  app.add_option("--topology", flags["topology"], "cube or ring")->capture_default_str();
  const std::pair<const char*, const char*> whatifs[] = {
      {"latency", "message start-up, both protocols (e.g. 275us)"},
      {"bandwidth", "channel bandwidth (e.g. 2.8MBps)"},
      {"per-hop", "per-hop cost: the channel latency (e.g. 10us)"},
      {"host-latency", "host (srm) link start-up: host-up and host-down latency (e.g. 1ms)"},
      {"host-bandwidth", "host (srm) link bandwidth: host-up and host-down (e.g. 1MBps)"},
      {"cpu-scale", "multiply every CPU cost: the host speed becomes clock / k"},
      {"memory", "node memory (e.g. 16MiB)"}};
  std::map<std::string, std::string> given;
  for (const auto& [k, help] : whatifs)
    app.add_option("--" + std::string(k), given[k], help);
  app.add_option("-o,--output", out,
                 "write to this file instead of standard output (-: standard output)");
  app.footer(whatif_help());
  if (int rc = parse(app, args); rc >= 0) return rc;
  if (names_stdout(out)) out.clear(); // standard output, as without the flag
  check_output_path(out, "--output"); // before any work: a missing directory says so

  std::string command = "zcube platform --machine " + flags["machine"] + " --nodes " +
                        flags["nodes"] + " --topology " + flags["topology"];
  for (const auto& [k, v] : given)
    if (!v.empty()) {
      flags[k] = v;
      command += " --" + k + " " + v;
    }
  const SimConfig c = config_from_flags(flags, "");
  if (c.machine.ends_with(".xml"))
    throw UsageError("--machine: expected ipsc2, ipsc860 or volvox (a built-in model)");
  PlatformEdits pe;
  pe.cpu_scale = c.overrides.cpu_scale.value_or(1.0);
  const std::string xml =
      platform_xml(edited(machine_spec(c.machine), c.overrides, command), c.nodes, c.topology, pe);
  if (out.empty()) {
    std::cout << xml;
    return 0;
  }
  write_text_file(out, xml); // names the file and the system's reason (e.g. a full disk)
  return 0;
}

ZC_COMMAND("platform", "write the SimGrid platform file of a machine model, what-ifs included",
           cmd_platform);

} // namespace zc::cli
