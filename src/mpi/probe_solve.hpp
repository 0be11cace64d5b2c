#pragma once
// The probe's fit (probe_cpu.hpp): the timed loops solved block by block, in order, for one
// multiplier a probe group on the prior table (probe_groups.hpp).
#include <vector>

#include <nlohmann/json.hpp>

#include "mpi/probe_harness.hpp"

namespace zc::cpu_probe {

// The multipliers of the loops' fit, one a group; every loop's fitted prediction written into
// `log`. `alone`: the multipliers rank 0 found timing alone (empty when this is that fit), whose
// split a block of several groups keeps.
std::vector<double> solve(const std::vector<Loop>& loops, const std::vector<double>& alone,
                          nlohmann::json& log);

} // namespace zc::cpu_probe
