#pragma once
// `zcube calibrate`: bounds the physical CPU cost estimates (machine/cpu_model.hpp) by the figures
// the seeds print, and validates the result on figures it was not fitted to.
//  1. Fit (iPSC/2): one multiplier per free cost group (machine.hpp cost_groups) of the 80386's
//     physical estimate, each kept within the operations' plausible range (0.5x..2x), so that the
//     simulated 16-node runs of Kurc et al. Table 2 (PAIR-RS and ZBUF-EXC, six scenes, three
//     phases: 36 figures) match. A phase time of the critical node is linear in the multipliers
//     given its waits, t = sum_g k_g A_g + wait (A_g: the group's operations that node charged in
//     the phase, at physical prices): bounded least squares on the relative errors, with a weak
//     pull towards the physical estimate, repeated at the new costs until the multipliers settle.
//  2. The multipliers correct the operation mixes (what the compiled program executes), which the
//     80386 and the i860 share; the i860's own clocks are not fitted. No Charles et al. figure
//     enters the fit: the iPSC/860 teapot speed-ups are predictions set beside 5.6 and 8.3.
//  3. Validation: leave-one-scene-out cross-validation of the fit (fit five scenes, predict the
//     sixth), and every fitted cost as a multiple of its physical estimate (plausibility).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace zc {

struct CalibrationOptions {
  std::string root; // source tree (scenes/)
  int jobs = 2;     // simulations at once
  int max_iterations = 12;
  // Weight of the pull of every multiplier towards 1 (the physical estimate), in relative-error
  // units: it settles groups the targets barely exercise.
  double ridge = 0.02;
  bool verbose = true; // progress on stderr
  // Groups kept at their physical estimate: by default the choice of the last `--select` run
  // (calibrated_costs.hpp kFixedGroups), the fewest free parameters the cross-validation supports.
  std::vector<std::string> fixed_groups = default_fixed_groups();
  bool cross_validate = true; // the leave-one-scene-out folds (about 250 short simulations)
  // Model selection: cross-validate every candidate set of fixed groups and fit with the one that
  // predicts the held-out scenes best (ties within half a point go to fewer free parameters).
  bool select = false;
  static std::vector<std::string> default_fixed_groups();
  static std::vector<std::vector<std::string>> candidate_fixed_groups();
};

// Runs the fit and its validation; returns fit.json's content: {"groups", "free_groups",
// "bounds", "scale", "at_bound", "tables", "targets", "crossval", "charles", "plausibility",
// "iterations", "rms_rel_error", "settings"}.
nlohmann::json calibrate(const CalibrationOptions& opt);

// The share of the cross-validation's held-out figures inside their 50, 80 and 90 % bands of the
// uncertainty model, and the 90 % bands' median half-width (repro/calibrate_coverage.cpp);
// `crossval` is calibrate()'s "crossval".
nlohmann::json fold_coverage(const nlohmann::json& crossval, const CalibrationOptions& opt);

// Writes results/calibration/{fit.json, targets.csv, crossval.csv, plausibility.csv,
// charles_prediction.csv, README.md} under out_dir.
void write_calibration_results(const nlohmann::json& fit, const std::string& out_dir);

// The generated header src/machine/calibrated_costs.hpp for this fit.
std::string calibrated_costs_header(const nlohmann::json& fit);

} // namespace zc
