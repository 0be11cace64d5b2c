#pragma once
// The calibration's fit (repro/calibrate.hpp, step 1): Kurc et al.'s Table 2 on the iPSC/2, one
// multiplier a free cost group, by the fixed-point iteration of a linearised bounded least-squares
// fit; and its leave-one-scene-out cross-validation (step 3).
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "repro/calibrate.hpp"

namespace zc::calibration {

// One target as a row of the linear model: the critical node's operations per group (at physical
// prices) and its time not spent computing.
struct PhaseRow {
  std::vector<double> a; // per group
  double wait = 0, time = 0, paper = 0;
  std::string id, scene;
};

struct KurcFit {
  std::vector<double> k;
  std::vector<PhaseRow> first, last; // rows at the physical estimate and at the fit
  nlohmann::json iterations = nlohmann::json::array();
};

std::vector<double> rel_errors(const std::vector<PhaseRow>& rows);
// Whether cost group g keeps its physical estimate in this fit.
bool is_fixed(std::size_t g, const CalibrationOptions& o);

// A fit's scenes and its name in the log.
using FitScenes = std::pair<std::vector<std::string>, std::string>;
// The fits of several sets of scenes, side by side (calibrate_fit.cpp).
std::vector<KurcFit> kurc_fits(const std::vector<FitScenes>& fits, const CalibrationOptions& o);
// The training scenes of each leave-one-scene-out fold (every scene but the held one).
std::vector<FitScenes> folds();
// Leave one scene out: fit the other five (fold_fits, in kurc_scenes' order), predict the sixth.
nlohmann::json cross_validate(const std::vector<KurcFit>& fold_fits, const CalibrationOptions& o);
nlohmann::json cross_validate(const CalibrationOptions& o);

} // namespace zc::calibration
