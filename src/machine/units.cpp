#include "machine/units.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <tuple>

#include "util/error.hpp"

namespace zc {
namespace {

// SimGrid's unit_scale: each generator is <unit, value, base (2 or 10), abbreviated prefixes>; the
// first entry of a name wins (std::map::emplace keeps it, as SimGrid's unordered_map does).
UnitTable scale(std::initializer_list<std::tuple<const char*, double, int, bool>> generators) {
  static const std::vector<std::string> bin_abbr = {"Ki", "Mi", "Gi", "Ti", "Pi", "Ei", "Zi", "Yi"},
                                        bin = {"kibi", "mebi", "gibi", "tebi",
                                               "pebi", "exbi", "zebi", "yobi"},
                                        dec_abbr = {"k", "M", "G", "T", "P", "E", "Z", "Y"},
                                        dec = {"kilo", "mega", "giga", "tera",
                                               "peta", "exa",  "zeta", "yotta"};
  UnitTable t;
  for (auto [unit, value, base, abbrev] : generators) {
    const double mult = base == 2 ? 1024.0 : 1000.0;
    const auto& prefixes = base == 2 ? (abbrev ? bin_abbr : bin) : (abbrev ? dec_abbr : dec);
    t.emplace(unit, value);
    for (const auto& prefix : prefixes)
      t.emplace(prefix + unit, value *= mult);
  }
  return t;
}

std::string unit_list(const UnitTable& units) {
  // The short, common ones: the whole table has up to 66 entries.
  std::string known;
  for (const auto& [u, f] : units)
    if (!u.empty() && u.size() <= 5 && u.find_first_of("PEZY") == std::string::npos)
      known += (known.empty() ? "" : ", ") + u;
  return known;
}

// xbt_parse_get_value_with_unit: strtod, then the rest of the string is the unit.
double parse_with(const std::string& text, const std::string& flag, const UnitTable& units,
                  const char* what, Unit rule, const char* example) {
  const char* b = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(b, &end);
  if (end == b || errno == ERANGE || !std::isfinite(v) || v < 0)
    throw UsageError(flag + " '" + text + "': expected a non-negative " + what + " (a finite " +
                     "number and a unit, e.g. " + example + ")");
  const std::string unit(end);
  if (unit.empty() && rule == Unit::Required)
    throw UsageError(flag + " '" + text + "': a " + what + " needs a unit, e.g. " + example +
                     " (units: " + unit_list(units) + ")");
  if (unit.empty()) return v;
  auto it = units.find(unit);
  if (it == units.end())
    throw UsageError(flag + " '" + text + "': unknown unit '" + unit +
                     "' (SimGrid's units: " + unit_list(units) + ")");
  if (!std::isfinite(v * it->second))
    throw UsageError(flag + " '" + text + "': beyond the largest " + what + " a double holds");
  return v * it->second;
}

} // namespace

const UnitTable& time_units() {
  static const UnitTable t = {{"w", 7 * 24 * 60 * 60},
                              {"d", 24 * 60 * 60},
                              {"h", 60 * 60},
                              {"m", 60},
                              {"s", 1.0},
                              {"ms", 1e-3},
                              {"us", 1e-6},
                              {"ns", 1e-9},
                              {"ps", 1e-12}};
  return t;
}

const UnitTable& bandwidth_units() {
  static const UnitTable t = scale({{"bps", 0.125, 2, true},
                                    {"bps", 0.125, 10, true},
                                    {"Bps", 1, 2, true},
                                    {"Bps", 1, 10, true}});
  return t;
}

const UnitTable& size_units() {
  static const UnitTable t =
      scale({{"b", 0.125, 2, true}, {"b", 0.125, 10, true}, {"B", 1, 2, true}, {"B", 1, 10, true}});
  return t;
}

const UnitTable& speed_units() {
  static const UnitTable t = scale({{"f", 1, 10, true}, {"flops", 1, 10, false}});
  return t;
}

double parse_time(const std::string& text, const std::string& flag, Unit rule) {
  return parse_with(text, flag, time_units(), "time", rule, "275us");
}

double parse_bandwidth(const std::string& text, const std::string& flag, Unit rule) {
  return parse_with(text, flag, bandwidth_units(), "bandwidth", rule, "2.8MBps");
}

double parse_bytes(const std::string& text, const std::string& flag, Unit rule) {
  return parse_with(text, flag, size_units(), "size", rule, "16MiB");
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
  return parse_with(text, flag, speed_units(), "speed", rule, "10Mf");
}

std::string format_double(double v) {
  char buf[64];
  auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, p);
}

} // namespace zc
