// Validation of algorithm options against their declarations (algorithm.hpp: OptionSpec), done
// once before any simulation starts, so a bad value is a usage error (exit 2) rather than a
// failure of the node that first reads it.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "algo/algorithm.hpp"
#include "machine/units.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

// A whole decimal integer in [min, max], or nothing.
bool integer_in(const std::string& s, long long min, long long max) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && end == s.data() + s.size() && !s.empty() && v >= min && v <= max;
}

bool list_in(const std::string& s, long long min, long long max) {
  std::size_t i = 0;
  while (true) {
    const std::size_t j = std::min(s.find(',', i), s.size());
    if (!integer_in(s.substr(i, j - i), min, max)) return false;
    if (j == s.size()) return true;
    i = j + 1;
  }
}

// Sizes with units, like every size flag (machine/units.hpp), each a whole byte count in range.
bool sizes_in(const std::string& s, long long min, long long max) {
  try {
    for (double b : parse_bytes_list(s, "--sizes"))
      if (b != std::floor(b) || b < double(min) || b > double(max)) return false;
    return true;
  } catch (const UsageError&) {
    return false;
  }
}

std::string expected(const OptionSpec& o) {
  const std::string range = std::to_string(o.min) + ".." + std::to_string(o.max);
  switch (o.kind) {
  case OptionSpec::Kind::Choice: {
    std::string c;
    for (const auto& v : o.choices)
      c += (c.empty() ? "" : " or ") + v;
    return c;
  }
  case OptionSpec::Kind::Integer:
    return "an integer in " + range;
  case OptionSpec::Kind::SizeList:
    return "comma-separated sizes with units (0B, 64B, 1KiB), whole bytes in " + range;
  case OptionSpec::Kind::NodeList:
    return "comma-separated node numbers in " + range;
  }
  return "";
}

bool valid(const OptionSpec& o, const std::string& v) {
  switch (o.kind) {
  case OptionSpec::Kind::Choice:
    return std::find(o.choices.begin(), o.choices.end(), v) != o.choices.end();
  case OptionSpec::Kind::Integer:
    return integer_in(v, o.min, o.max);
  case OptionSpec::Kind::SizeList:
    return sizes_in(v, o.min, o.max);
  case OptionSpec::Kind::NodeList:
    return list_in(v, o.min, o.max);
  }
  return false;
}

} // namespace

void validate_options(const Algorithm& a, AlgorithmOptions& o, bool cube) {
  for (const auto& [k, v] : o.values) {
    auto spec = std::find_if(a.options.begin(), a.options.end(),
                             [&](const OptionSpec& s) { return s.name == k; });
    if (spec == a.options.end())
      throw UsageError("--" + k + " does not apply to algorithm " + a.name);
    if (!valid(*spec, v))
      throw UsageError("--" + k + " '" + v + "': expected " + expected(*spec) + " (" + a.name +
                       ")");
  }
  for (const auto& s : a.options)
    o.defaults[s.name] = s.default_value;
  if (o.frames < 1) throw UsageError("--frames must be at least 1");
  if (o.frames > 1 && !a.renders_frames)
    throw UsageError("--frames " + std::to_string(o.frames) + ": " + a.name +
                     " renders one picture (only sequential and elastic render a camera path)");
  if (a.needs_cube && !cube)
    throw UsageError("--topology: " + a.name + " runs on a hypercube only (--topology cube)");
}

std::vector<std::pair<OptionSpec, std::string>> all_option_specs() {
  std::vector<std::pair<OptionSpec, std::string>> out;
  for (const auto& a : algorithms())
    for (const auto& s : a.options) {
      auto it = std::find_if(out.begin(), out.end(),
                             [&](const auto& p) { return p.first.name == s.name; });
      if (it == out.end())
        out.emplace_back(s, a.name);
      else
        it->second += ", " + a.name;
    }
  return out;
}

} // namespace zc
