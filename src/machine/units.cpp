#include "machine/units.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "util/error.hpp"

namespace zc {
namespace {

std::string unit_list(const std::map<std::string, double>& units) {
  std::string known;
  for (const auto& [u, f] : units)
    if (!u.empty()) known += (known.empty() ? "" : ", ") + u;
  return known;
}

double parse_with(const std::string& text, const std::string& flag,
                  const std::map<std::string, double>& units, const char* what, Unit rule,
                  const char* example) {
  const char* b = text.data();
  const char* e = b + text.size();
  double v = 0;
  auto [p, ec] = std::from_chars(b, e, v);
  if (ec != std::errc() || !std::isfinite(v) || v < 0)
    throw UsageError(flag + " '" + text + "': expected a non-negative " + what);
  const std::string unit(p, e);
  if (unit.empty() && rule == Unit::Required)
    throw UsageError(flag + " '" + text + "': a " + what + " needs a unit, e.g. " + example +
                     " (units: " + unit_list(units) + ")");
  auto it = units.find(unit);
  if (it == units.end())
    throw UsageError(flag + " '" + text + "': unknown unit '" + unit + "' (use " +
                     unit_list(units) + ")");
  if (!std::isfinite(v * it->second))
    throw UsageError(flag + " '" + text + "': beyond the largest " + what + " a double holds");
  return v * it->second;
}

} // namespace

double parse_time(const std::string& text, const std::string& flag, Unit rule) {
  static const std::map<std::string, double> u = {{"", 1},      {"s", 1},     {"ms", 1e-3},
                                                  {"us", 1e-6}, {"ns", 1e-9}, {"ps", 1e-12},
                                                  {"m", 60},    {"h", 3600}};
  return parse_with(text, flag, u, "time", rule, "275us");
}

double parse_bandwidth(const std::string& text, const std::string& flag, Unit rule) {
  static const std::map<std::string, double> u = {
      {"", 1},           {"Bps", 1},           {"kBps", 1e3},
      {"KBps", 1e3},     {"MBps", 1e6},        {"GBps", 1e9},
      {"KiBps", 1024.0}, {"MiBps", 1048576.0}, {"GiBps", 1073741824.0},
      {"bps", 0.125},    {"kbps", 125.0},      {"Kbps", 125.0},
      {"Mbps", 125e3},   {"Gbps", 125e6}};
  return parse_with(text, flag, u, "bandwidth", rule, "2.8MBps");
}

double parse_bytes(const std::string& text, const std::string& flag, Unit rule) {
  static const std::map<std::string, double> u = {
      {"", 1},     {"B", 1},        {"kB", 1e3},        {"KB", 1e3},          {"MB", 1e6},
      {"GB", 1e9}, {"KiB", 1024.0}, {"MiB", 1048576.0}, {"GiB", 1073741824.0}};
  return parse_with(text, flag, u, "size", rule, "16MiB");
}

std::vector<double> parse_bytes_list(const std::string& text, const std::string& flag) {
  std::vector<double> v;
  std::size_t i = 0;
  while (true) {
    const std::size_t j = std::min(text.find(',', i), text.size());
    v.push_back(parse_bytes(text.substr(i, j - i), flag, Unit::Required));
    if (j == text.size()) return v;
    i = j + 1;
  }
}

double parse_speed(const std::string& text, const std::string& flag, Unit rule) {
  // SimGrid host speeds: "f" is one flop per second (platform DTD: 1Gf, 10Mf, 3.5kf).
  static const std::map<std::string, double> u = {
      {"", 1},      {"f", 1},     {"kf", 1e3},     {"Mf", 1e6},     {"Gf", 1e9},
      {"Tf", 1e12}, {"flops", 1}, {"kflops", 1e3}, {"Mflops", 1e6}, {"Gflops", 1e9}};
  return parse_with(text, flag, u, "speed", rule, "10Mf");
}

std::string format_double(double v) {
  char buf[64];
  auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, p);
}

} // namespace zc
