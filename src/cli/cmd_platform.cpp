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
MachineSpec edited(MachineSpec spec, const WhatIfs& w, const std::string& command) {
  WhatIfs on_figures = w;
  on_figures.reset("cpu-scale"); // written as the host speed (PlatformEdits)
  MachineFigures f = machine_figures(spec, 1);
  apply_what_ifs(on_figures, f);
  spec.net = f.net;
  spec.memory_bytes = f.memory_bytes.front();
  const double lowest = spec.net.per_hop_s + kSmpiEnvelopeBytes * spec.net.per_byte_s;
  const double startup = std::min(spec.net.startup_short_s, spec.net.startup_long_s);
  if (startup < lowest) {
    // Name the flag that moved the figure past the other: the start-up given, else the channel's.
    const std::string need = format_double(lowest * 1e6) + " us";
    if (w.get("latency"))
      throw UsageError("--latency must be at least the per-hop cost plus 16 bytes at the channel "
                       "rate (" +
                       need + "): SMPI's receive overhead would be < 0");
    throw UsageError(std::string(w.get("bandwidth") ? "--bandwidth" : "--per-hop") +
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
  // Every what-if but --cost-scale (a run's units, not a machine's figure), from the flag table.
  std::map<std::string, std::string> given;
  add_run_flag_options(app, given, [](const RunFlag& f) {
    return f.group == RunFlag::Group::WhatIf && f.name != "cost-scale";
  });
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
  const RunConfig c = config_from_flags(flags, "");
  if (is_platform_file(c.machine))
    throw UsageError("--machine: expected ipsc2, ipsc860 or volvox (a built-in model)");
  PlatformEdits pe;
  pe.cpu_scale = c.what_ifs.cpu_scale();
  const std::string xml =
      platform_xml(edited(machine_spec(c.machine), c.what_ifs, command), c.nodes, c.topology, pe);
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
