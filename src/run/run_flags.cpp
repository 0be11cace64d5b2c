#include "run/run_flags.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "machine/clock_limits.hpp"
#include "machine/machine.hpp"
#include "machine/units.hpp"
#include "util/error.hpp"
#include "util/image_size.hpp"

namespace zc {

std::vector<std::pair<OptionSpec, std::string>> run_option_specs() {
  auto all = all_option_specs();
  std::erase_if(all, [](const auto& p) { return p.second == "pingpong"; }); // zcube pingpong's
  return all;
}

const std::vector<std::string>& run_flag_names() {
  static const std::vector<std::string> f = [] {
    std::vector<std::string> v = {"machine",        "nodes",     "topology", "fidelity",
                                  "algorithm",      "scene",     "size",     "frames",
                                  "latency",        "bandwidth", "per-hop",  "host-latency",
                                  "host-bandwidth", "cpu-scale", "memory",   "cost-scale"};
    for (const auto& [s, algos] : run_option_specs())
      v.push_back(s.name);
    return v;
  }();
  return f;
}

namespace {

constexpr int kMaxFrames = 10000; // --frames

int parse_int(const std::string& s, const std::string& flag) {
  std::size_t used = 0;
  int v = 0;
  try {
    v = std::stoi(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || s.empty())
    throw UsageError("--" + flag + " '" + s + "': expected an integer");
  return v;
}

double parse_positive(const std::string& s, const std::string& flag) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end || !(v > 0) || !std::isfinite(v))
    throw UsageError("--" + flag + " '" + s + "': expected a positive number");
  return v;
}

// What-ifs beyond the clock's bounds (machine/clock_limits.hpp; the run also fails then,
// sim/simulation.cpp).
const char* const kClockWhy = ": slower costs push the simulated clock (a double) past 2^52 ns, "
                              "where compute times are rounded";

// A delay what-if (--latency, --per-hop, --host-latency): a time with its unit, at most 1 h.
std::optional<double> delay_flag(const std::map<std::string, std::string>& v,
                                 const std::string& flag) {
  if (!v.count(flag)) return std::nullopt;
  const double s = parse_time(v.at(flag), "--" + flag, Unit::Required);
  if (s > kMaxDelay_s)
    throw UsageError("--" + flag + " '" + v.at(flag) + "': above 1 h" + kClockWhy);
  return s;
}

// A rate what-if (--bandwidth, --host-bandwidth): a bandwidth with its unit, at least 1 Bps.
std::optional<double> rate_flag(const std::map<std::string, std::string>& v,
                                const std::string& flag) {
  if (!v.count(flag)) return std::nullopt;
  const double bps = parse_bandwidth(v.at(flag), "--" + flag, Unit::Required);
  if (bps < kMinBandwidth_Bps)
    throw UsageError("--" + flag + " '" + v.at(flag) + "': below 1 Bps" + kClockWhy);
  return bps;
}

// The what-if flags, each checked against the range the simulated clock can time.
Overrides what_ifs(const std::map<std::string, std::string>& v, const std::string& machine,
                   bool xml) {
  Overrides o;
  o.latency_s = delay_flag(v, "latency");
  o.bandwidth_Bps = rate_flag(v, "bandwidth");
  o.per_hop_s = delay_flag(v, "per-hop");
  if (o.per_hop_s) {
    const auto& names = machine_names();
    if (!xml && std::find(names.begin(), names.end(), machine) != names.end() &&
        machine_spec(machine).net.switching == Switching::StoreAndForward)
      throw UsageError("--per-hop: " + machine + " is store-and-forward: each hop pays a whole " +
                       "start-up and transfer, there is no per-hop cost to change (use " +
                       "--latency, the start-up of each hop, or --bandwidth)");
  }
  // The host (srm) link to node 0 (docs/machines.md), held to the node channels' limits.
  o.host_latency_s = delay_flag(v, "host-latency");
  o.host_bandwidth_Bps = rate_flag(v, "host-bandwidth");
  if (v.count("cpu-scale")) {
    o.cpu_scale = parse_positive(v.at("cpu-scale"), "cpu-scale");
    // 1e-3 keeps a scaled cycle (25 ns and up) above the simulator's 1e-12 s timing precision.
    if (*o.cpu_scale < 1e-3 || *o.cpu_scale > 1e3)
      throw UsageError("--cpu-scale '" + v.at("cpu-scale") +
                       "': outside 1e-3..1e3 (faster cycles fall below the simulator's timing "
                       "precision; slower ones push the clock past 2^52 ns)");
  }
  if (v.count("memory")) {
    o.memory_bytes = parse_bytes(v.at("memory"), "--memory", Unit::Required);
    if (!(*o.memory_bytes > 0))
      throw UsageError("--memory '" + v.at("memory") + "': a node needs some memory (> 0 bytes)");
    if (*o.memory_bytes > kMaxNodeMemory_bytes) // as a platform file's zcube.node_memory
      throw UsageError("--memory '" + v.at("memory") +
                       "': above 1 PiB, where a node's byte counts lose precision");
  }
  if (v.count("cost-scale")) {
    o.cost_scale = parse_positive(v.at("cost-scale"), "cost-scale");
    // Every cost and the simulator's timing precision (1e-12 s) are multiplied by k; outside
    // this range the scaled precision leaves normal doubles (1e-320 spun SimGrid forever).
    if (*o.cost_scale < 1e-6 || *o.cost_scale > 1e6)
      throw UsageError("--cost-scale '" + v.at("cost-scale") +
                       "': outside 1e-6..1e6 (it also scales the simulator's 1e-12 s timing "
                       "precision, which must stay a normal number above the clock's rounding)");
  }
  return o;
}

} // namespace

SimConfig config_from_flags(const std::map<std::string, std::string>& v, const std::string& scene) {
  auto get = [&](const char* k, const char* def) {
    auto it = v.find(k);
    return it == v.end() ? std::string(def) : it->second;
  };
  SimConfig c;
  c.machine = get("machine", "ipsc2");
  c.topology = parse_topology(get("topology", "cube"));
  c.fidelity = parse_fidelity(get("fidelity", "circuit"));
  const bool xml = c.machine.ends_with(".xml");
  c.nodes = v.count("nodes") ? parse_int(v.at("nodes"), "nodes") : (xml ? 0 : 1);
  if (!xml) check_node_count(c.topology, c.nodes);
  if (xml && v.count("topology"))
    throw UsageError("--topology " + v.at("topology") + " with --machine " + c.machine +
                     ": a platform file states its own topology (write one with zcube platform "
                     "--topology " +
                     v.at("topology") + ")");
  c.algorithm = get("algorithm", "sequential");
  c.scene_path = get("scene", scene.c_str());
  if (v.count("size")) {
    const ImageSize s = parse_image_size(v.at("size"));
    c.width = s.width;
    c.height = s.height;
  }
  c.options.frames = v.count("frames") ? parse_int(v.at("frames"), "frames") : 1;
  // Each picture is simulated and rendered again by the sequential renderer for the comparison:
  // about a millisecond of host time at 8x8, far more at real sizes.
  if (c.options.frames > kMaxFrames)
    throw UsageError("--frames " + v.at("frames") + ": at most " + std::to_string(kMaxFrames) +
                     " pictures (each is simulated and rendered again for the comparison; "
                     "longer camera paths take hours of host time)");
  c.overrides = what_ifs(v, c.machine, xml);
  for (const auto& [s, algos] : run_option_specs())
    if (v.count(s.name)) c.options.values[s.name] = v.at(s.name);
  // The algorithm and its options are checked here, so a bad combination fails only its point.
  validate_options(find_algorithm(c.algorithm), c.options, xml || c.topology == Topology::Cube);
  return c;
}

} // namespace zc
