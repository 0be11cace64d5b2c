#include "run/what_if.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "machine/clock_limits.hpp"
#include "machine/units.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

using Q = WhatIfSpec::Quantity;

// Past these bounds the simulated clock (a double of seconds) no longer times nanoseconds
// (machine/clock_limits.hpp).
const char* const kClockWhy = ": slower costs push the simulated clock (a double) past 2^52 ns, "
                              "where compute times are rounded";

[[noreturn]] void refuse(const WhatIfSpec& s, const std::string& text, const std::string& why) {
  throw UsageError("--" + s.flag + " '" + text + "': " + why);
}

void check_delay(const WhatIfSpec& s, const std::string& text, double seconds) {
  if (seconds > kMaxDelay_s) refuse(s, text, std::string("above 1 h") + kClockWhy);
}

void check_rate(const WhatIfSpec& s, const std::string& text, double bps) {
  if (bps < kMinBandwidth_Bps) refuse(s, text, std::string("below 1 Bps") + kClockWhy);
}

void check_memory(const WhatIfSpec& s, const std::string& text, double bytes) {
  if (!(bytes > 0)) refuse(s, text, "a node needs some memory (> 0 bytes)");
  if (bytes > kMaxNodeMemory_bytes) // as a platform file's zcube.node_memory
    refuse(s, text, "above 1 PiB, where a node's byte counts lose precision");
}

// A factor flag's range: `lo`..`hi`, and why.
auto factor_range(double lo, double hi, std::string why) {
  return [lo, hi, why](const WhatIfSpec& s, const std::string& text, double k) {
    if (k < lo || k > hi) refuse(s, text, why);
  };
}

// The text a relative value's result is named by in an error: "x0.1 (2.75e-05 s)".
std::string result_text(const WhatIfValue& v, double si, const char* unit) {
  std::ostringstream o;
  o << "x" << v.value << " (" << si << " " << unit << ")";
  return o.str();
}

// A delay figure (a start-up, a per-hop cost): set, or scaled and checked.
void edit_delay(const WhatIfSpec& s, const WhatIfValue& v, double& figure) {
  if (!v.relative) {
    figure = v.value;
    return;
  }
  figure *= v.value;
  check_delay(s, result_text(v, figure, "s"), figure);
}

// A per-byte figure set from a rate, or divided by the rate's factor, and checked.
void edit_per_byte(const WhatIfSpec& s, const WhatIfValue& v, double& per_byte) {
  if (!v.relative) {
    per_byte = 1.0 / v.value;
    return;
  }
  per_byte /= v.value;
  check_rate(s, result_text(v, 1.0 / per_byte, "B/s"), 1.0 / per_byte);
}

void apply_latency(const WhatIfSpec& s, const WhatIfValue& v, MachineFigures& m) {
  if (!v.relative) {
    m.net.startup_short_s = m.net.startup_long_s = v.value; // one start-up for every size
    return;
  }
  edit_delay(s, v, m.net.startup_short_s); // each protocol range keeps its own
  edit_delay(s, v, m.net.startup_long_s);
}

void apply_per_hop(const WhatIfSpec& s, const WhatIfValue& v, MachineFigures& m) {
  if (m.net.switching == Switching::StoreAndForward)
    throw UsageError("--per-hop: " + m.machine +
                     " is store-and-forward: each hop pays a whole start-up and transfer, there "
                     "is no per-hop cost to change (use --latency, the start-up of each hop, or "
                     "--bandwidth)");
  edit_delay(s, v, m.net.per_hop_s);
}

void apply_memory(const WhatIfSpec& s, const WhatIfValue& v, MachineFigures& m) {
  for (double& bytes : m.memory_bytes) {
    bytes = v.relative ? bytes * v.value : v.value;
    if (v.relative) check_memory(s, result_text(v, bytes, "B"), bytes);
  }
}

// --cost-scale: every cost, CPU and network, times k (stiffness checks: the same run in other
// units).
void apply_cost_scale(const WhatIfSpec&, const WhatIfValue& v, MachineFigures& m) {
  const double k = v.value;
  m.cpu_factor *= k;
  for (double* f : {&m.net.startup_short_s, &m.net.startup_long_s, &m.net.per_byte_s,
                    &m.net.per_hop_s, &m.net.host_startup_s, &m.net.host_per_byte_s})
    *f *= k;
}

std::vector<WhatIfSpec> make_specs() {
  std::vector<WhatIfSpec> v;
  v.push_back({"latency", "latency_s", Q::Time,
               "message start-up (absolute: one start-up for every message size; xK: each "
               "protocol range's start-up times K)",
               "275us or x0.1", "0 .. 1 h", check_delay, apply_latency});
  v.push_back({"bandwidth", "bandwidth_Bps", Q::Rate, "channel bandwidth (per-byte cost = 1/rate)",
               "2.8MBps or x4", ">= 1 Bps", check_rate,
               [](const WhatIfSpec& s, const WhatIfValue& x, MachineFigures& m) {
                 edit_per_byte(s, x, m.net.per_byte_s);
               }});
  v.push_back({"per-hop", "per_hop_s", Q::Time,
               "per-hop cost of a circuit (the channel latency; none on store-and-forward)",
               "10us or x2", "0 .. 1 h", check_delay, apply_per_hop});
  v.push_back({"host-latency", "host_latency_s", Q::Time,
               "host link start-up (the host, the papers' SRM, to node 0)", "1ms or x0.5",
               "0 .. 1 h", check_delay,
               [](const WhatIfSpec& s, const WhatIfValue& x, MachineFigures& m) {
                 edit_delay(s, x, m.net.host_startup_s);
               }});
  v.push_back({"host-bandwidth", "host_bandwidth_Bps", Q::Rate,
               "host link bandwidth (its per-byte cost = 1/rate)", "1MBps or x2", ">= 1 Bps",
               check_rate, [](const WhatIfSpec& s, const WhatIfValue& x, MachineFigures& m) {
                 edit_per_byte(s, x, m.net.host_per_byte_s);
               }});
  v.push_back({"cpu-scale", "cpu_scale", Q::Factor,
               "multiply every CPU cost (0.25 = a CPU 4x faster)", "0.25", "1e-3 .. 1e3",
               // 1e-3 keeps a scaled cycle (25 ns and up) above the simulator's 1e-12 s precision.
               factor_range(1e-3, 1e3,
                            "outside 1e-3..1e3 (faster cycles fall below the simulator's timing "
                            "precision; slower ones push the clock past 2^52 ns)"),
               [](const WhatIfSpec&, const WhatIfValue& x, MachineFigures& m) {
                 m.cpu_factor *= x.value;
               }});
  v.push_back({"memory", "memory_bytes", Q::Bytes, "node memory", "16MiB or x0.5", "> 0 .. 1 PiB",
               check_memory, apply_memory});
  // Every cost and the simulator's timing precision (1e-12 s) are multiplied by k; outside this
  // range the scaled precision leaves normal doubles (1e-320 spun SimGrid forever).
  v.push_back({"cost-scale", "cost_scale", Q::Factor,
               "multiply every cost, CPU and network (the same run in other units)", "10",
               "1e-6 .. 1e6",
               factor_range(1e-6, 1e6,
                            "outside 1e-6..1e6 (it also scales the simulator's 1e-12 s timing "
                            "precision, which must stay a normal number above the clock's "
                            "rounding)"),
               apply_cost_scale});
  return v;
}

// A plain positive finite number ("0.25"), else UsageError.
double parse_factor(const WhatIfSpec& s, const std::string& text, const std::string& number,
                    bool zero_allowed) {
  char* end = nullptr;
  const double v = std::strtod(number.c_str(), &end);
  if (number.empty() || end == number.c_str() || *end || !std::isfinite(v) || v < 0 ||
      (v == 0 && !zero_allowed))
    refuse(s, text,
           std::string("expected ") +
               (s.quantity == Q::Factor ? "a positive number" : "a value with its unit or xK") +
               " (e.g. " + s.example + ")");
  return v;
}

double parse_absolute(const WhatIfSpec& s, const std::string& text) {
  const std::string flag = "--" + s.flag;
  switch (s.quantity) {
  case Q::Time:
    return parse_time(text, flag, Unit::Required);
  case Q::Rate:
    return parse_bandwidth(text, flag, Unit::Required);
  case Q::Bytes:
    return parse_bytes(text, flag, Unit::Required);
  case Q::Factor:
    return parse_factor(s, text, text, false);
  }
  throw std::logic_error("unknown what-if quantity");
}

} // namespace

std::string WhatIfSpec::factor_key() const {
  std::string k = flag;
  for (char& c : k)
    if (c == '-') c = '_';
  return k + "_factor";
}

const std::vector<WhatIfSpec>& what_if_specs() {
  static const std::vector<WhatIfSpec> specs = make_specs();
  return specs;
}

const WhatIfSpec* find_what_if(const std::string& flag) {
  for (const auto& s : what_if_specs())
    if (s.flag == flag) return &s;
  return nullptr;
}

WhatIfValue parse_what_if(const WhatIfSpec& s, const std::string& text) {
  if (text.starts_with("x")) {
    // A start-up or per-hop cost may become 0 (x0); a rate or a memory may not.
    const double k = parse_factor(s, text, text.substr(1), s.quantity == Q::Time);
    if (s.quantity == Q::Factor) {
      s.check(s, text, k);
      return {k, false};
    }
    return {k, true};
  }
  const double si = parse_absolute(s, text);
  s.check(s, text, si);
  return {si, false};
}

void WhatIfs::set(const std::string& flag, WhatIfValue v) {
  if (!find_what_if(flag)) throw std::logic_error("no what-if --" + flag);
  values_[flag] = v;
}

std::optional<WhatIfValue> WhatIfs::get(const std::string& flag) const {
  const auto it = values_.find(flag);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

double WhatIfs::factor(const std::string& flag) const {
  const auto v = get(flag);
  return v ? v->value : 1.0;
}

std::vector<std::pair<const WhatIfSpec*, WhatIfValue>> WhatIfs::in_order() const {
  std::vector<std::pair<const WhatIfSpec*, WhatIfValue>> out;
  for (const auto& s : what_if_specs())
    if (const auto v = get(s.flag)) out.emplace_back(&s, *v);
  return out;
}

void apply_what_ifs(const WhatIfs& w, MachineFigures& m) {
  const double one_way_per_byte = m.net.per_byte_s;
  for (const auto& [spec, v] : w.in_order())
    spec->apply(*spec, v, m);
  // A what-if channel rate keeps the two-way total's ratio to it (the T800's acknowledges scale
  // with the link's bit rate).
  if (m.net.both_ways_Bps > 0 && m.net.per_byte_s != one_way_per_byte)
    m.net.both_ways_Bps *= one_way_per_byte / m.net.per_byte_s;
}

MachineFigures machine_figures(const MachineSpec& m, int nodes) {
  return {m.name, m.net, std::vector<double>(std::size_t(std::max(nodes, 1)), m.memory_bytes), 1.0};
}

std::map<std::string, double> what_if_columns(const WhatIfs& w) {
  std::map<std::string, double> out;
  for (const auto& [spec, v] : w.in_order())
    out[v.relative ? spec->factor_key() : spec->key] = v.value;
  return out;
}

std::string what_if_text(const WhatIfSpec& s, const WhatIfValue& v) {
  std::ostringstream o;
  o.precision(6);
  if (v.relative) {
    o << "x" << v.value;
    return o.str();
  }
  switch (s.quantity) {
  case Q::Time:
    o << v.value * 1e6 << " us";
    break;
  case Q::Rate:
    o << v.value / 1e6 << " MB/s";
    break;
  case Q::Bytes:
    o << v.value / 1048576 << " MiB";
    break;
  case Q::Factor:
    o << v.value;
    break;
  }
  return o.str();
}

std::string what_if_flag_text(const WhatIfSpec& s, const WhatIfValue& v) {
  // A stream: GCC 12 at -O3 reports a false -Wrestrict on string concatenation here.
  std::ostringstream o;
  if (v.relative) o << 'x';
  o << format_double(v.value);
  if (!v.relative && s.quantity != Q::Factor)
    o << (s.quantity == Q::Time ? "s" : s.quantity == Q::Rate ? "Bps" : "B");
  return o.str();
}

std::string compose_what_if_text(const WhatIfSpec& s, const std::string& own,
                                 const std::string& set) {
  const WhatIfValue x = parse_what_if(s, set);
  if (!x.relative || own.empty()) return set;
  return what_if_flag_text(s, compose_what_if(parse_what_if(s, own), x));
}

WhatIfValue compose_what_if(const WhatIfValue& own, const WhatIfValue& set) {
  if (!set.relative) return set;
  return {own.value * set.value, own.relative};
}

} // namespace zc
