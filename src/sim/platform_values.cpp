#include "sim/platform_values.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "machine/units.hpp"
#include "sim/simgrid_args.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

constexpr long kMaxNodes = 1024;

std::vector<std::string> split_on(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::size_t at = 0;
  for (std::size_t next; (next = s.find(sep, at)) != s.npos; at = next + 1)
    out.push_back(s.substr(at, next - at));
  out.push_back(s.substr(at));
  return out;
}

// A whole number of 1 to 4 digits, else -1.
int small_number(const std::string& s) {
  if (s.empty() || s.size() > 4 ||
      !std::all_of(s.begin(), s.end(), [](unsigned char c) { return c >= '0' && c <= '9'; }))
    return -1;
  return std::stoi(s);
}

// One figure with its unit through zcube's parser (SimGrid's units), positive when `positive`.
std::string figure_problem(const std::string& value,
                           const std::function<double(const std::string&)>& parse, bool positive,
                           const char* what) {
  if (value.find(',') != std::string::npos)
    return std::string("zcube models one ") + what + " (no power states or lists)";
  try {
    const double v = parse(value);
    if (positive && !(v > 0)) return std::string("a ") + what + " must be > 0";
  } catch (const UsageError& e) {
    const std::string m = e.what(); // "value 'text': reason"
    const auto colon = m.find("': ");
    return colon == m.npos ? m : m.substr(colon + 3);
  }
  return "";
}

std::string radical_problem(const std::string& value) {
  std::set<int> nodes;
  for (const std::string& part : split_on(value, ',')) {
    const auto dash = part.find('-');
    const int lo = small_number(part.substr(0, dash));
    const int hi = dash == part.npos ? lo : small_number(part.substr(dash + 1));
    if (lo < 0 || hi < lo) return "expected node numbers a-b or a, 0 <= a <= b < 10000";
    if (long(nodes.size()) + hi - lo + 1 > kMaxNodes) return "zcube simulates at most 1024 nodes";
    for (int i = lo; i <= hi; ++i)
      if (!nodes.insert(i).second) return "node " + std::to_string(i) + " is named twice";
  }
  return "";
}

std::string dimensions_problem(const std::string& value) {
  long product = 1;
  for (const std::string& d : split_on(value, ',')) {
    const int n = small_number(d);
    if (n < 1) return "expected dimensions 1..1024 separated by commas";
    product *= n;
    if (product > kMaxNodes) return "zcube simulates at most 1024 nodes";
  }
  return "";
}

std::string choice_problem(const std::string& value, const std::set<std::string>& allowed,
                           const std::string& why) {
  return allowed.count(value) ? "" : why;
}

} // namespace

std::string attribute_value_problem(AttributeKind kind, const std::string& v) {
  using K = AttributeKind;
  switch (kind) {
  case K::Name:
    if (v.empty()) return "an empty name";
    return std::any_of(v.begin(), v.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; })
               ? "a name with control characters"
               : "";
  case K::Text:
    return "";
  case K::Version:
    return choice_problem(v, {"4.1"}, "zcube reads SimGrid's platform format version 4.1");
  case K::Routing:
    return choice_problem(v, {"Full", "Floyd", "Dijkstra", "DijkstraCache", "None"},
                          "zcube routes zones by Full, Floyd, Dijkstra, DijkstraCache or None");
  case K::Speed:
    return figure_problem(
        v, [](const std::string& s) { return parse_speed(s, "speed", Unit::Required); }, true,
        "speed");
  case K::Bandwidth:
    return figure_problem(
        v, [](const std::string& s) { return parse_bandwidth(s, "bandwidth", Unit::Required); },
        true, "bandwidth");
  case K::Latency:
    return figure_problem(
        v, [](const std::string& s) { return parse_time(s, "latency", Unit::Required); }, false,
        "latency");
  case K::Core:
    return choice_problem(v, {"1"}, "zcube models one processor per node (core=\"1\")");
  case K::Radical:
    return radical_problem(v);
  case K::Dimensions:
    return dimensions_problem(v);
  case K::ClusterTopology:
    return choice_problem(v, {"TORUS"},
                          "zcube's cubes and rings are SimGrid tori (topology=\"TORUS\")");
  case K::ClusterSharing:
    return choice_problem(v, {"SPLITDUPLEX"},
                          "zcube's channels are full-duplex (sharing_policy=\"SPLITDUPLEX\")");
  case K::LinkSharing:
    return choice_problem(v, {"SHARED"},
                          "zcube reads a link as one direction of a channel, or a duplex total "
                          "(sharing_policy=\"SHARED\", the default)");
  case K::YesNo:
    return choice_problem(v, {"YES", "NO", "yes", "no"}, "expected YES or NO");
  }
  return "";
}

std::string unmodelled_element_reason(const std::string& e) {
  static const std::map<std::string, std::string> why = {
      {"actor", "zcube runs its own node programs: a platform file deploys none"},
      {"process", "zcube runs its own node programs: a platform file deploys none"},
      {"argument", "zcube runs its own node programs: a platform file deploys none"},
      {"trace", "zcube models constant speeds and bandwidths (no traces)"},
      {"trace_connect", "zcube models constant speeds and bandwidths (no traces)"},
      {"include", "zcube reads one self-contained file"},
      {"router", std::string("zcube's routes join the hosts node0..nodeP-1 and ") +
                     kHostComputerName + " only (no routers)"},
      {"AS", "an element of SimGrid's older formats: version 4.1 says <zone>"},
      {"ASroute", "an element of SimGrid's older formats: version 4.1 says <zoneRoute>"},
  };
  const auto it = why.find(e);
  return it != why.end() ? it->second
                         : "not an element of the platforms zcube models (platforms/README.md "
                           "lists them)";
}

std::string unmodelled_attribute_reason(const std::string& e, const std::string& a) {
  if (a.ends_with("_file")) return "zcube models constant figures (no trace files)";
  if (a == "pstate") return "zcube models one speed per node (no power states)";
  if (a == "coordinates") return "zcube routes by its topology, not by coordinates";
  return "not an attribute zcube models on <" + e + "> (platforms/README.md lists them)";
}

std::vector<std::pair<int, int>> radical_ranges(const std::string& radical) {
  std::vector<std::pair<int, int>> r;
  for (const std::string& part : split_on(radical, ',')) {
    const auto dash = part.find('-');
    const int lo = small_number(part.substr(0, dash));
    r.push_back({lo, dash == part.npos ? lo : small_number(part.substr(dash + 1))});
  }
  return r;
}

long radical_count(const std::string& radical) {
  long n = 0;
  for (auto [lo, hi] : radical_ranges(radical))
    n += hi - lo + 1;
  return n;
}

long dimensions_product(const std::string& dimensions) {
  long p = 1;
  for (const std::string& d : split_on(dimensions, ','))
    p *= small_number(d);
  return p;
}

std::string config_setting_problem(const std::string& key, const std::string& value) {
  if (key == kStartupConfig) return ""; // read, and checked, as the start-up (platform_load)
  if (key.starts_with("smpi/")) {
    for (const auto& [k, v] : kFlowConfig)
      if (key == k)
        return value == v ? ""
                          : "zcube runs no SMPI program and writes " + std::string(v) +
                                " here (the value under which SMPI times messages as zcube does)";
    return "zcube runs no SMPI program: SMPI's settings change nothing";
  }
  return setting_problem(key, value);
}

std::string zone_property_problem(const std::string& id) {
  static const std::set<std::string> known = [] {
    std::set<std::string> k = {"zcube.machine",     "zcube.topology",    "zcube.switching",
                               "zcube.node_memory", "zcube.os_resident", "zcube.messages"};
    CostTable cycles;
    for (auto& [field, v] : cycles.fields())
      k.insert("zcube.cycles." + field.substr(5));
    return k;
  }();
  return known.count(id) ? ""
                         : "not a property zcube reads (platforms/README.md lists the zcube.* "
                           "properties of the machine's zone)";
}

} // namespace zc
