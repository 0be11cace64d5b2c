#include "machine/machine.hpp"

#include <iterator>

#include "machine/calibrated_costs.hpp"
#include "machine/cpu_model.hpp"
#include "machine/machine_data.hpp"
#include "machine/machine_file.hpp"
#include "util/error.hpp"

namespace zc {

double CostTable::seconds(const Counters& c) const {
  double s = 0;
#define ZC_COST_SUM(f) s += double(c.f) * f;
  ZC_COUNTER_FIELDS(ZC_COST_SUM)
#undef ZC_COST_SUM
  return s;
}

CostTable CostTable::scaled(double k) const {
  CostTable t = *this;
#define ZC_COST_SCALE(f) t.f *= k;
  ZC_COUNTER_FIELDS(ZC_COST_SCALE)
#undef ZC_COST_SCALE
  return t;
}

std::vector<std::pair<std::string, double*>> CostTable::fields() {
  std::vector<std::pair<std::string, double*>> v;
#define ZC_COST_NAME(f) v.emplace_back("cost_" #f, &f);
  ZC_COUNTER_FIELDS(ZC_COST_NAME)
#undef ZC_COST_NAME
  return v;
}

double NetworkParams::message_time(double bytes, int hops) const {
  if (hops <= 0) return 0;
  if (switching == Switching::StoreAndForward) return hops * (startup(bytes) + bytes * per_byte_s);
  return startup(bytes) + bytes * per_byte_s + (hops - 1) * per_hop_s;
}

const std::vector<CounterGroup>& cost_groups() {
  static const std::vector<CounterGroup> g = {
      {"geometry",
       {"vertices_transformed", "triangles_in", "triangles_culled", "triangles_clipped",
        "triangles_setup", "triangles_estimated", "triangles_tessellated"}},
      {"spans",
       {"spans", "rows_scanned", "edge_walks", "span_starts", "sort_steps", "records_fetched"}},
      {"pixels",
       {"pixels_generated", "pixels_tested", "pixels_written", "pixels_final", "texels_fetched",
        "far_lines", "distant_lines"}},
      {"clear", {"pixels_cleared"}},
      {"merge", {"merge_ops"}},
      {"packing",
       {"bytes_packed", "records_packed", "locations_scanned", "wire_records", "wire_bytes",
        "triangles_packed"}},
      {"list_merge", {"list_merges"}},
      {"scanline", {"wpa_tested", "wpa_appended"}}};
  return g;
}

CostTable scale_groups(const CostTable& t, const std::vector<double>& scale) {
  return scale_groups(t, cost_groups(), scale);
}

CostTable scale_groups(const CostTable& t, const std::vector<CounterGroup>& groups,
                       const std::vector<double>& scale) {
  CostTable out = t;
  for (auto& [id, v] : out.fields())
    for (std::size_t g = 0; g < groups.size() && g < scale.size(); ++g)
      for (const auto& f : groups[g].fields)
        if (id == "cost_" + f) *v *= scale[g];
  return out;
}

std::vector<double> group_seconds(const CostTable& prices, const std::vector<CounterGroup>& groups,
                                  const Counters& work) {
  std::vector<double> out;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    std::vector<double> only(groups.size(), 0.0);
    only[g] = 1.0;
    out.push_back(scale_groups(prices, groups, only).seconds(work));
  }
  return out;
}

std::vector<double> calibrated_group_scale() {
  static_assert(std::size(calibrated::kGroupScale) == 8, "one multiplier per cost group");
  return std::vector<double>(std::begin(calibrated::kGroupScale),
                             std::end(calibrated::kGroupScale));
}

// The calibration's multipliers correct the operation mixes (what the compiled program does), which
// both CPUs share; each CPU's instruction clocks are its own and are not fitted.
CostTable i386_costs() {
  return cpu_seconds(cpu_model("i80386"), calibrated_group_scale());
}
CostTable i860_costs() {
  return cpu_seconds(cpu_model("i860xr"), calibrated_group_scale());
}
CostTable prior_i386_costs() {
  return cpu_seconds(cpu_model("i80386"));
}

namespace {

// Every machine built in (machines/*.json), in file name order. The calibration's multipliers
// correct the operation mixes, which every CPU shares: each machine's table is its CPU's, scaled.
const std::vector<MachineSpec>& builtin_specs() {
  static const std::vector<MachineSpec> v = [] {
    std::vector<MachineSpec> out;
    for (const auto& f : machine_data::machine_files()) {
      MachineSpec m = parse_machine_file(f.path, f.text, cpu_names());
      m.cost = cpu_seconds(cpu_model(m.cpu), calibrated_group_scale());
      m.cost_calibrated = calibrated::kFitted;
      out.push_back(std::move(m));
    }
    return out;
  }();
  return v;
}

} // namespace

const std::vector<std::string>& machine_names() {
  static const std::vector<std::string> n = [] {
    std::vector<std::string> out;
    for (const auto& m : builtin_specs())
      out.push_back(m.name);
    return out;
  }();
  return n;
}

const MachineSpec& machine_spec(const std::string& name) {
  for (const auto& s : builtin_specs())
    if (s.name == name) return s;
  std::string names;
  for (const auto& n : machine_names())
    names += (names.empty() ? "" : ", ") + n;
  throw UsageError("--machine '" + name + "': expected " + names + " or a platform .xml");
}

} // namespace zc
