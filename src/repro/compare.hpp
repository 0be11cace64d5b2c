#pragma once
// `zcube compare`: a measured report (MPI backend) against a predicted one (the simulator on a
// platform that models the same cluster), phase by phase.
#include <string>

#include <nlohmann/json.hpp>

#include "repro/table.hpp"

namespace zc {

// Reads a report; InputError naming the file when it is not a zcube report.
nlohmann::json read_report(const std::string& path);

// Rows: phase, measured_s, predicted_s, rel_error (predicted against measured), in the measured
// report's phase order, then phases only one side has, then the total. UsageError when the two
// runs are of different algorithms or node counts.
Table compare_reports(const nlohmann::json& measured, const nlohmann::json& predicted);

} // namespace zc
