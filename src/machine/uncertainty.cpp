#include "machine/uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "machine/calibrated_costs.hpp"
#include "machine/cpu_model.hpp"
#include "util/error.hpp"

namespace zc {

CostTable apply_draw(const CostTable& t, const ModelDraw& d) {
  return d.group_scale.empty() ? t : scale_groups(t, d.group_scale);
}

NetworkParams apply_draw(const NetworkParams& n, const ModelDraw& d) {
  NetworkParams r = n;
  r.startup_short_s *= d.startup;
  r.startup_long_s *= d.startup;
  r.per_byte_s *= d.per_byte;
  r.per_hop_s *= d.per_hop;
  r.host_startup_s *= d.host_startup;
  r.host_per_byte_s *= d.host_per_byte;
  if (r.both_ways_Bps > 0) r.both_ways_Bps /= d.per_byte;
  return r;
}

namespace {

// A range from absolute figures around a nominal one (docs/machines.md's tables).
FigureRange around(double nominal, double low, double high, const char* source) {
  return {low / nominal, high / nominal, source};
}

// The fitted multipliers' spread and the structural error, shared by the machines whose cost
// tables come from the fitted operation mixes.
void add_fit(UncertaintySpec& s) {
  for (const auto& row : calibrated::kFoldScale)
    s.fold_scales.emplace_back(std::begin(row), std::end(row));
  const std::size_t n = std::size(calibrated::kResidualPhases);
  for (std::size_t i = 0; i < n; ++i)
    s.phase_sigma[calibrated::kResidualPhases[i]] = calibrated::kResidualRms[i];
  s.phase_sigma_default = calibrated::kResidualRms[n];
}

// The host link (Blazek's SRM to node 0): an assumption with a wide range (docs/machines.md,
// "The host computer's link").
void add_host_link(UncertaintySpec& s) {
  s.host_startup = around(1e-3, 0.275e-3, 2e-3, "docs/machines.md, host link start-up");
  s.host_per_byte = around(1.0, 1 / 2.8, 1 / 0.5, "docs/machines.md, host link rate");
}

UncertaintySpec ipsc2() {
  UncertaintySpec s;
  s.machine = "ipsc2";
  s.known = true;
  s.startup = around(275, 275, 490, "docs/machines.md, iPSC/2 start-up");
  s.per_byte = around(1 / 2.8, 1 / 2.8, 1 / 2.5, "docs/machines.md, iPSC/2 per byte");
  s.per_hop = around(10, 1, 30, "docs/machines.md, iPSC/2 per hop");
  s.os_resident = around(512, 256, 1024, "docs/memory.md, NX/2");
  add_host_link(s);
  add_fit(s);
  return s;
}

// The i860's cycle counts are the data sheet's; what a compiled loop takes on it (pipelining,
// its 8 KB cache) is not measured anywhere: one factor over the operations' plausible range.
FigureRange i860_clocks() {
  return {plausible_low(), plausible_high(), "docs/machines.md, one cost per loop (range)"};
}

UncertaintySpec ipsc860() {
  UncertaintySpec s;
  s.machine = "ipsc860";
  s.known = true;
  s.startup = {65.0 / 75, 160.0 / 136, "docs/machines.md, iPSC/860 start-up"};
  s.per_byte = around(0.36, 0.36, 0.4, "docs/machines.md, iPSC/860 per byte");
  s.per_hop = around(10, 10, 30, "docs/machines.md, iPSC/860 per hop");
  s.os_resident = around(1024, 512, 2048, "docs/memory.md, NX");
  s.cpu_clocks = i860_clocks();
  add_host_link(s);
  add_fit(s);
  return s;
}

UncertaintySpec volvox() {
  UncertaintySpec s;
  s.machine = "volvox";
  s.known = true;
  s.startup = around(50, 10, 200, "docs/machines.md, Volvox start-up per hop");
  s.per_byte = around(1 / 1.7, 1 / 1.74, 1 / 1.6, "docs/machines.md, T800 link rate");
  s.os_resident = around(1024, 512, 2048, "docs/memory.md, NX (assumed as the iPSC/860's)");
  s.cpu_clocks = i860_clocks();
  add_host_link(s);
  add_fit(s);
  return s;
}

// A deterministic stream of uniforms in (0, 1) for (seed, draw, stream): splitmix64, so that a
// draw is the same whatever else was drawn before it.
double uniform(std::uint64_t seed, std::uint64_t draw, std::uint64_t stream) {
  std::uint64_t z = seed ^ (draw * 0x9E3779B97F4A7C15ull) ^ (stream * 0xD1B54A32D192ED03ull);
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return (double(z >> 11) + 0.5) * 0x1p-53;
}

double normal(std::uint64_t seed, std::uint64_t draw, std::uint64_t stream) {
  const double u1 = uniform(seed, draw, 2 * stream), u2 = uniform(seed, draw, 2 * stream + 1);
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
}

// A factor whose median is 1 (the nominal figure, as likely too high as too low), triangular in
// log space on each side with its mode at 1: half the draws in [low, 1], half in [1, high]. A side
// the range does not have (the nominal at an end of its range) leaves those draws at 1.
double split_triangular_log(const FigureRange& r, double u) {
  const double a = std::log(std::min(r.low, 1.0)), b = std::log(std::max(r.high, 1.0));
  if (u < 0.5) return std::exp(a * (1 - std::sqrt(u / 0.5)));
  return std::exp(b * (1 - std::sqrt(1 - (u - 0.5) / 0.5)));
}

std::uint64_t name_stream(const std::string& name) {
  std::uint64_t h = 1469598103934665603ull; // FNV-1a
  for (unsigned char ch : name)
    h = (h ^ ch) * 1099511628211ull;
  return 1000 + (h % 1000000007ull);
}

// The fitted multipliers of draw d relative to the nominal ones: the folds' jackknife
// covariance, sum_k z_k (l_k - mean) sqrt((n-1)/n), kept in the plausible range.
std::vector<double> fit_factors(const UncertaintySpec& s, std::uint64_t seed, std::uint64_t d) {
  const std::size_t groups = cost_groups().size();
  std::vector<double> f(groups, 1.0);
  const std::size_t n = s.fold_scales.size();
  if (n < 2) return f;
  const std::vector<double> nominal = calibrated_group_scale();
  std::vector<double> z(n);
  for (std::size_t k = 0; k < n; ++k)
    z[k] = normal(seed, d, 10 + k);
  const double k_jack = std::sqrt(double(n - 1) / double(n));
  for (std::size_t g = 0; g < groups; ++g) {
    double mean = 0;
    for (const auto& row : s.fold_scales)
      mean += std::log(row[g]) / double(n);
    double dl = 0;
    for (std::size_t k = 0; k < n; ++k)
      dl += z[k] * (std::log(s.fold_scales[k][g]) - mean) * k_jack;
    const double m = std::clamp(nominal[g] * std::exp(dl), plausible_low(), plausible_high());
    f[g] = m / nominal[g];
  }
  return f;
}

} // namespace

double ModelDraw::phase(const std::string& name) const {
  const auto it = phase_sigma.find(name);
  const double sigma = it == phase_sigma.end() ? phase_sigma_default : it->second;
  return sigma > 0 ? std::exp(sigma * normal(seed, index, name_stream(name))) : 1.0;
}

const UncertaintySpec& uncertainty_spec(const std::string& machine) {
  static const UncertaintySpec specs[] = {ipsc2(), ipsc860(), volvox()};
  for (const auto& s : specs)
    if (s.machine == machine) return s;
  static const UncertaintySpec unknown{};
  return unknown;
}

const std::vector<std::string>& model_parameters() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& g : cost_groups())
      n.push_back("cpu." + g.name);
    for (const char* x : {"startup", "per_byte", "per_hop", "host_startup", "host_per_byte"})
      n.emplace_back(x);
    return n;
  }();
  return names;
}

ModelDraw scaled_parameter(std::size_t p, double factor) {
  ModelDraw d;
  const std::size_t groups = cost_groups().size();
  if (p < groups) {
    d.group_scale.assign(groups, 1.0);
    d.group_scale[p] = factor;
    return d;
  }
  double* net[] = {&d.startup, &d.per_byte, &d.per_hop, &d.host_startup, &d.host_per_byte};
  if (p - groups >= std::size(net)) throw std::out_of_range("model parameter");
  *net[p - groups] = factor;
  return d;
}

std::vector<ModelDraw> model_draws(const std::string& machine, int n, std::uint64_t seed) {
  return model_draws(uncertainty_spec(machine), n, seed);
}

std::vector<ModelDraw> model_draws(const UncertaintySpec& s, int n, std::uint64_t seed) {
  std::vector<ModelDraw> out;
  for (int i = 0; i < n; ++i) {
    const auto d = std::uint64_t(i);
    ModelDraw m;
    m.group_scale = fit_factors(s, seed, d);
    const double clocks = split_triangular_log(s.cpu_clocks, uniform(seed, d, 1));
    for (double& g : m.group_scale)
      g *= clocks;
    m.startup = split_triangular_log(s.startup, uniform(seed, d, 2));
    m.per_byte = split_triangular_log(s.per_byte, uniform(seed, d, 3));
    m.per_hop = split_triangular_log(s.per_hop, uniform(seed, d, 4));
    m.host_startup = split_triangular_log(s.host_startup, uniform(seed, d, 5));
    m.host_per_byte = split_triangular_log(s.host_per_byte, uniform(seed, d, 6));
    m.os_resident = split_triangular_log(s.os_resident, uniform(seed, d, 7));
    m.phase_sigma = s.phase_sigma;
    m.phase_sigma_default = s.phase_sigma_default;
    m.seed = seed;
    m.index = d;
    out.push_back(std::move(m));
  }
  return out;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double pos = q * double(v.size() - 1);
  const auto i = std::size_t(pos);
  if (i + 1 >= v.size()) return v.back();
  return v[i] + (pos - double(i)) * (v[i + 1] - v[i]);
}

} // namespace zc
