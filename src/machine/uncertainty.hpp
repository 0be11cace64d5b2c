#pragma once
// The uncertainty model of a machine's figures (docs/uncertainty.md): what a prediction's band is
// made of. A draw is one set of machine figures, as factors on the nominal ones:
//  - the fitted CPU multipliers' joint spread, from the calibration's leave-one-scene-out folds
//    (their jackknife covariance, in log space);
//  - every unfitted figure within its documented range (docs/machines.md): start-ups, per-byte
//    and per-hop costs, the host link, the i860's clocks, the node operating system's share,
//    each with its median at the nominal figure: half the draws below it, half above, each side
//    triangular in log space with its mode at the nominal and the range's end as its limit;
//  - the model's own structural error: a factor on the CPU work of each phase, log-normal with
//    the root mean square of the cross-validation's log errors of that phase.
// Draw d is the same function of (seed, d) for every run: the points of a study are priced by the
// same draws, so the band of a difference is the band of the difference.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "machine/machine.hpp"

namespace zc {

// One set of machine figures, as factors on the nominal ones (1: nominal).
struct ModelDraw {
  std::vector<double> group_scale; // per cost group (cost_groups() order); empty: all 1
  double startup = 1, per_byte = 1, per_hop = 1, host_startup = 1, host_per_byte = 1;
  double os_resident = 1;
  // Structural error: a factor on the CPU work charged inside a phase, exp(sigma z) with z a
  // standard normal of (seed, draw, the phase's name): the same phase gets the same factor in
  // every run priced by this draw. sigma by name, `sigma_default` for the other phases.
  std::map<std::string, double> phase_sigma;
  double phase_sigma_default = 0;
  std::uint64_t seed = 0, index = 0;

  double phase(const std::string& name) const;
};

// The machine's figures under a draw: cost tables and network figures scaled.
CostTable apply_draw(const CostTable& t, const ModelDraw& d);
NetworkParams apply_draw(const NetworkParams& n, const ModelDraw& d);

// A figure's documented range as multiples of its nominal value.
struct FigureRange {
  double low = 1, high = 1;
  std::string source; // where the range is documented
};

// What the model says about one machine's figures.
struct UncertaintySpec {
  std::string machine;
  bool known = false; // false: a machine zcube has no ranges for (a probed or custom platform)
  FigureRange startup, per_byte, per_hop, host_startup, host_per_byte, os_resident;
  FigureRange cpu_clocks; // a factor on every CPU cost (the i860's clocks; 1..1 on the 80386)
  // Log-space covariance of the fitted multipliers: the folds' scales (cost_groups() order).
  std::vector<std::vector<double>> fold_scales;
  // Structural sigma (log) per phase name, and for the phases not named.
  std::map<std::string, double> phase_sigma;
  double phase_sigma_default = 0;
};

const UncertaintySpec& uncertainty_spec(const std::string& machine);

// The parameters a sensitivity is taken against, in order: the cost groups, then start-up,
// per-byte, per-hop, host start-up, host per-byte.
const std::vector<std::string>& model_parameters();
// The nominal draw with parameter `p` (model_parameters() index) multiplied by `factor`.
ModelDraw scaled_parameter(std::size_t p, double factor);

// Draws 0..n-1 of the model of `machine` (seed fixes them; the same for every run).
std::vector<ModelDraw> model_draws(const std::string& machine, int n, std::uint64_t seed);
std::vector<ModelDraw> model_draws(const UncertaintySpec& spec, int n, std::uint64_t seed);

// Quantiles of `v` (linear interpolation between order statistics, as numpy's default).
double quantile(std::vector<double> v, double q);

} // namespace zc
