#include "machine/machine.hpp"

#include <iterator>

#include "machine/calibrated_costs.hpp"
#include "machine/cpu_model.hpp"
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

const std::vector<CostGroup>& cost_groups() {
  static const std::vector<CostGroup> g = {
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

CostTable scale_groups(const CostTable& t, const std::vector<CostGroup>& groups,
                       const std::vector<double>& scale) {
  CostTable out = t;
  for (auto& [id, v] : out.fields())
    for (std::size_t g = 0; g < groups.size() && g < scale.size(); ++g)
      for (const auto& f : groups[g].fields)
        if (id == "cost_" + f) *v *= scale[g];
  return out;
}

std::vector<double> group_seconds(const CostTable& prices, const std::vector<CostGroup>& groups,
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

std::vector<MachineSpec> make_specs() {
  std::vector<MachineSpec> v;
  {
    MachineSpec m;
    m.name = "ipsc2";
    m.description = "Intel iPSC/2: 80386+80387 16 MHz nodes, DCM circuit-switched hypercube";
    m.memory_bytes = 4.0 * 1048576;     // 4 MB base (docs/machines.md)
    m.os_resident_bytes = 512.0 * 1024; // NX/2 + program: 256 KiB..1 MiB (docs/memory.md)
    m.net.startup_short_s = 275e-6;     // Blazek ch. IV, read as microseconds (docs/machines.md)
    m.net.startup_long_s = 275e-6;
    m.net.short_max_bytes = 100;
    m.net.per_byte_s = 1.0 / 2.8e6; // 2.8 MB/s channel (Nugent 1988)
    // The same Direct-Connect Module as the iPSC/860, where Bokhari 1990 measured 10-30 us a hop;
    // the low end, as the DCM routes the header in hardware (docs/machines.md).
    m.net.per_hop_s = 10e-6;
    m.net.switching = Switching::Circuit;
    m.net.host_startup_s = 1e-3;  // SRM link: assumption, Ethernet-class (docs/machines.md)
    m.net.host_per_byte_s = 1e-6; // ~1 MB/s: assumption
    m.cpu = "i80386";
    m.cost = i386_costs();
    m.cost_calibrated = calibrated::kFitted;
    v.push_back(m);
  }
  {
    MachineSpec m;
    m.name = "ipsc860";
    m.description = "Intel iPSC/860: i860 XR 40 MHz nodes, DCM circuit-switched hypercube";
    m.memory_bytes = 8.0 * 1048576;      // ORNL CSEP
    m.os_resident_bytes = 1024.0 * 1024; // NX + program: 0.5..2 MiB (docs/memory.md)
    m.net.startup_short_s = 75e-6;       // Bokhari 1990 (docs/machines.md, low-medium confidence)
    m.net.startup_long_s = 136e-6;
    m.net.short_max_bytes = 100;
    m.net.per_byte_s = 0.36e-6;
    m.net.per_hop_s = 10e-6; // 10-30 us per hop (Bokhari; Dunigan)
    m.net.switching = Switching::Circuit;
    m.net.host_startup_s = 1e-3;
    m.net.host_per_byte_s = 1e-6;
    m.cpu = "i860xr";
    m.cost = i860_costs();
    m.cost_calibrated = calibrated::kFitted;
    v.push_back(m);
  }
  {
    MachineSpec m;
    m.name = "volvox";
    m.description = "Archipel Volvox: i860 compute + T800 transputer links, store-and-forward";
    m.memory_bytes = 8.0 * 1048576;      // assumption: i860 board as the iPSC/860's
    m.os_resident_bytes = 1024.0 * 1024; // assumption: as the iPSC/860's NX (docs/memory.md)
    m.net.startup_short_s = 50e-6;       // assumption (docs/machines.md): software overhead per hop
    m.net.startup_long_s = 50e-6;
    m.net.short_max_bytes = 100;
    m.net.per_byte_s = 1.0 / 1.7e6; // T800 link, ~1.7 MB/s achieved one way
    m.net.both_ways_Bps = 2.35e6;   // T800 link, both directions busy: 2.35 MB/s in all
    m.net.per_hop_s = 0;            // the per-hop cost is the whole store-and-forward step
    m.net.switching = Switching::StoreAndForward;
    m.net.host_startup_s = 1e-3;
    m.net.host_per_byte_s = 1e-6;
    m.cpu = "i860xr";
    m.cost = i860_costs();
    m.cost_calibrated = calibrated::kFitted;
    v.push_back(m);
  }
  return v;
}

} // namespace

const std::vector<std::string>& machine_names() {
  static const std::vector<std::string> n = {"ipsc2", "ipsc860", "volvox"};
  return n;
}

const MachineSpec& machine_spec(const std::string& name) {
  static const std::vector<MachineSpec> specs = make_specs();
  for (const auto& s : specs)
    if (s.name == name) return s;
  throw UsageError("--machine '" + name + "': expected ipsc2, ipsc860, volvox or a platform .xml");
}

} // namespace zc
