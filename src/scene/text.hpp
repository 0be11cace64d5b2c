#pragma once
// Small text helpers shared by the scene parsers: strict number parsing (the whole token must be a
// finite number), splitting, and shortest round-trip formatting of doubles.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace zc::text {

std::string_view trim(std::string_view s);
// Splits on spaces and tabs (and on commas too when `commas` is set); no empty tokens.
std::vector<std::string_view> split(std::string_view s, bool commas = false);
std::optional<double> to_double(std::string_view s); // finite values only
std::optional<float> to_float(std::string_view s);   // finite in float range only
// Why `s` is not a float to_float takes ("not a number: 'x'", "out of the range of a float: ..."),
// empty when it is one.
std::string float_problem(std::string_view s);
std::optional<long long> to_int(std::string_view s);
std::string fmt(double v); // shortest text that parses back to exactly v
std::string fmt(float v);
std::string lower(std::string_view s);
// A line's keyword: its text up to the first space or tab.
inline std::string_view keyword(std::string_view line) {
  std::size_t j = 0;
  while (j < line.size() && line[j] != ' ' && line[j] != '\t')
    ++j;
  return line.substr(0, j);
}
std::string read_file(const std::string& path);    // throws InputError(path, 0, ...) if unreadable
std::string directory_of(const std::string& path); // "" or "dir/"
std::string join_path(const std::string& dir, const std::string& rel);

} // namespace zc::text
