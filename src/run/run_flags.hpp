#pragma once
// The flags of `zcube run` as text (name without dashes -> value) and the one place that turns them
// into a SimConfig: used by run, pingpong, sweep (one map per point) and regress (runs.json).
#include <map>
#include <string>
#include <vector>

#include "run/config.hpp"

namespace zc {

// The algorithm options zcube run takes (every algorithm's but pingpong's, which has its own
// command), each with the algorithms that take it.
std::vector<std::pair<OptionSpec, std::string>> run_option_specs();

// Every flag name, in the order sweeps list their columns.
const std::vector<std::string>& run_flag_names();

// The configuration the flags describe; absent flags take zcube run's defaults (ipsc2, 1 node or
// a platform .xml's own count, cube, circuit, sequential, `scene`). UsageError/InputError name the
// flag at fault; an algorithm option the algorithm does not take is an error.
SimConfig config_from_flags(const std::map<std::string, std::string>& flags,
                            const std::string& scene);

} // namespace zc
