#pragma once
// `zcube calibrate`: fits the CPU cost tables to the figures the seeds print.
//  1. iPSC/2 (80386): one multiplier per cost group (machine/machine.hpp cost_groups) of the prior
//     table, so that the simulated 16-node runs of Kurc et al. Table 2 (PAIR-RS and ZBUF-EXC, six
//     scenes, three phases: 36 figures) match. Each phase time of the critical node is linear in
//     the costs given the waits: t = sum_g k_g * A_g + wait, with A_g the group's operations that
//     node charged in the phase, priced at the prior. Non-negative least squares on the relative
//     errors (with a weak pull of every multiplier towards 1 so a group no target exercises keeps
//     its prior), then the runs are repeated at the new costs until the multipliers settle (the
//     waits and the critical node depend on the costs).
//  2. i860 (iPSC/860 and Volvox, the same 40 MHz part): the fitted 80386 table divided by one
//     speed ratio, fitted so that the simulated iPSC/860 hypercube gives the teapot speed-ups of
//     Charles et al. §6 (5.6 on 8 nodes, 8.3 on 16): least squares on the relative errors,
//     golden-section search over log(ratio).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace zc {

struct CalibrationOptions {
  std::string root; // source tree (scenes/)
  int jobs = 2;     // simulations at once
  int max_iterations = 12;
  double ridge =
      0.02; // weight of the pull towards the prior, per multiplier, in relative-error units
  bool verbose = true; // progress on stderr
  // Groups kept at the prior (--fix GROUP): none by default. Fixing "packing" (the only group
  // exercised by few targets: messages gathered from several runs of scanlines) moves the rms
  // error of the iPSC/2 fit from 7 % to 13 % (results/calibration/README.md).
  std::vector<std::string> fixed_groups;
};

// Runs the fit; returns fit.json's content: {"groups", "i386_scale", "i860_ratio", "tables",
// "targets": [{id, machine, paper, prior, fitted, rel_error_prior, rel_error_fitted}],
// "iterations", "rms_rel_error"}.
nlohmann::json calibrate(const CalibrationOptions& opt);

// Writes results/calibration/{fit.json, targets.csv, README.md} under out_dir.
void write_calibration_results(const nlohmann::json& fit, const std::string& out_dir);

// The generated header src/machine/calibrated_costs.hpp for this fit.
std::string calibrated_costs_header(const nlohmann::json& fit);

} // namespace zc
