#pragma once
// The calibration's prediction of Charles et al. §6 on the iPSC/860 (repro/calibrate.hpp, step 2):
// the teapot's speed-ups at the fitted multipliers and at the physical estimate, beside the
// paper's; predicted, not fitted.
#include <vector>

#include <nlohmann/json.hpp>

#include "repro/calibrate.hpp"

namespace zc::calibration {

nlohmann::json charles_prediction(const std::vector<double>& k, const CalibrationOptions& o);

} // namespace zc::calibration
