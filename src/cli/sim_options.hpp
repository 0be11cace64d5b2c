#pragma once
// Flags shared by every command that simulates: machine, nodes, topology, fidelity and the what-if
// overrides (SimGrid-style units: 275us, 2.8MBps, 16MiB).
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "run/run_flags.hpp"
#include "sim/simulation.hpp"

namespace zc::cli {

// Adds --<name> for every flag of the run flag table (run/run_flags.hpp) that `want` takes, its
// text going to values[name] (empty: not given). `lists`: each takes comma-separated values (zcube
// sweep). The help shows the table's value form, default and meaning.
void add_run_flag_options(CLI::App& app, std::map<std::string, std::string>& values,
                          const std::function<bool(const RunFlag&)>& want, bool lists = false);

// The flags given (non-empty values), machine and scene found among the bundled data when they
// are not files from the working directory (cli/paths.hpp).
std::map<std::string, std::string> given_flags(const std::map<std::string, std::string>& values);

struct SimFlags {
  std::map<std::string, std::string> values;   // machine, nodes, topology, fidelity, what-ifs
  std::map<std::string, std::string> defaults; // a command's own defaults (pingpong: nodes 2)
  std::vector<std::string> cfg, log;           // passed to SimGrid as --cfg=... and --log=...

  void add_to(CLI::App& app);
  // The given flags as text (run/run_flags.hpp), with the command's defaults, for
  // config_from_flags.
  std::map<std::string, std::string> flags() const;
  // --cfg name:value and --log settings as SimGrid arguments (UsageError on a malformed one).
  std::vector<std::string> simgrid_args() const;
  // Fills cfg's machine, nodes, topology, fidelity and what-ifs (UsageError on bad values).
  void apply(RunConfig& cfg) const;
};

// --cfg, --log and --help-cfg of the commands that run batches of simulations (sweep, reproduce,
// regress, calibrate): the settings go to every simulation of the process.
struct BatchSimGridFlags {
  std::vector<std::string> cfg, log;
  void add_to(CLI::App& app);
  // Checks the settings (UsageError) and hands them to every batch (repro/simulate).
  void apply() const;
};

// --cfg and --log as SimGrid arguments, checked against `fidelity` ("": a batch's mix).
std::vector<std::string> simgrid_args_of(const std::vector<std::string>& cfg,
                                         const std::vector<std::string>& log,
                                         const std::string& fidelity);

} // namespace zc::cli

namespace zc::cli {
// The help footer of every simulating command: units and ranges of the what-ifs, and each
// machine's own figures.
std::string whatif_help();

// --help-cfg: SimGrid's own list of its settings, then the process ends (exit status 0).
[[noreturn]] void print_simgrid_settings();

// One line per what-if override and SimGrid setting in force (empty when there is none), so a
// run never uses a changed figure without saying so.
std::string describe_overrides(const RunConfig& cfg);
} // namespace zc::cli
