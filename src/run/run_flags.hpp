#pragma once
// The one table of the flags that describe a run: the run's own (machine, nodes, topology,
// fidelity, algorithm, scene, size, frames), the what-ifs (run/what_if.hpp) and the algorithms'
// options (algo/algorithm.hpp: OptionSpec), each declared once with its value form, default and
// help. `zcube run`'s and `zcube pingpong`'s options, `zcube sweep`'s list-valued flags and
// columns, `zcube regress --set`, the help and the docs' flag table (`zcube help flags`) are made
// from it, and config_from_flags is the one place the text becomes a RunConfig.
#include <map>
#include <string>
#include <vector>

#include "run/config.hpp"

namespace zc {

struct RunFlag {
  enum class Group { Run, WhatIf, Option };
  std::string name; // without dashes
  Group group = Group::Run;
  std::string value_form;   // "INT", "WxH", "275us or x0.1", "a|b|c"
  std::string default_text; // "" when the default depends on other flags or there is none
  std::string help;
};

// Every flag, in the order sweeps list their columns: run flags, what-ifs, options.
const std::vector<RunFlag>& run_flags();
const RunFlag* find_run_flag(const std::string& name); // null when none has that name

// The algorithm options zcube run takes (every algorithm's but pingpong's, which has its own
// command), each with the algorithms that take it.
std::vector<std::pair<OptionSpec, std::string>> run_option_specs();

// Every flag name, in the order of run_flags().
const std::vector<std::string>& run_flag_names();

// The configuration the flags describe; absent flags take zcube run's defaults (ipsc2, 1 node or
// a platform .xml's own count, cube, circuit, sequential, `scene`). UsageError/InputError name the
// flag at fault; an algorithm option the algorithm does not take is an error. A built-in machine's
// what-ifs are applied to its figures here, so a factor that takes one out of bounds fails here.
RunConfig config_from_flags(const std::map<std::string, std::string>& flags,
                            const std::string& scene);

// The flags as a Markdown table (docs/user-guide.md holds it; a test keeps the two equal).
std::string run_flags_markdown();

} // namespace zc
