#pragma once
// The calibration's plausibility check (repro/calibrate.hpp, step 3): every fitted cost of every
// CPU model as a multiple of its physical estimate.
#include <vector>

#include <nlohmann/json.hpp>

namespace zc::calibration {

nlohmann::json plausibility(const std::vector<double>& k);

} // namespace zc::calibration
