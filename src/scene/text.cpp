#include "scene/text.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "util/error.hpp"
#include "util/input_file.hpp"

namespace zc::text {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() &&
         (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '\n'))
    s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view s, bool commas) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  auto sep = [&](char c) { return c == ' ' || c == '\t' || c == '\r' || (commas && c == ','); };
  while (i < s.size()) {
    while (i < s.size() && sep(s[i]))
      ++i;
    std::size_t j = i;
    while (j < s.size() && !sep(s[j]))
      ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

std::optional<double> to_double(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double v = 0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size() || s.empty() || !std::isfinite(v))
    return std::nullopt;
  return v;
}

std::optional<float> to_float(std::string_view s) {
  // Read as a double, then rounded to the float zcube keeps: a magnitude below the smallest float
  // rounds towards 0 (from_chars<float> refused 1e-50 as out of range), one above its largest is
  // refused (float_problem says so).
  const auto d = to_double(s);
  if (!d || std::fabs(*d) > double(std::numeric_limits<float>::max())) return std::nullopt;
  return float(*d);
}

std::string float_problem(std::string_view s) {
  std::string quoted = "'"; // appended piecewise: GCC 12 -O3 reports a false -Wrestrict on a+b+c
  quoted.append(s).append("'");
  if (to_float(s)) return "";
  if (to_double(s)) return "out of the range of a float (magnitude at most 3.4e38): " + quoted;
  double v = 0;
  std::string_view t = !s.empty() && s.front() == '+' ? s.substr(1) : s;
  auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec == std::errc::result_out_of_range) return "out of the range of a double: " + quoted;
  if (ec == std::errc() && p == t.data() + t.size() && !t.empty())
    return "not a finite number: " + quoted; // inf, nan
  return "not a number: " + quoted;
}

std::optional<long long> to_int(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  long long v = 0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

std::string fmt(double v) {
  char buf[64];
  auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  (void)ec;
  return std::string(buf, p);
}

std::string fmt(float v) {
  char buf[64];
  auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  (void)ec;
  return std::string(buf, p);
}

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return r;
}

std::string read_file(const std::string& path) {
  check_input_file(path); // a FIFO would block the read for ever
  std::error_code ec;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open file");
  // Read straight into a string of the file's size (a stringstream copied it twice); a file that
  // is not a regular file (a pipe) has no size and is read to its end.
  std::string s;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && std::filesystem::is_regular_file(path, ec)) {
    s.resize(std::size_t(size));
    in.read(s.data(), std::streamsize(s.size()));
    s.resize(std::size_t(in.gcount()));
    if (in.gcount() == std::streamsize(size) && in.peek() == std::char_traits<char>::eof())
      return s;
  }
  std::ostringstream rest;
  rest << in.rdbuf();
  return s + rest.str();
}

std::string directory_of(const std::string& path) {
  auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

std::string join_path(const std::string& dir, const std::string& rel) {
  if (rel.empty() || rel.front() == '/' || dir.empty()) return rel;
  return dir + rel;
}

} // namespace zc::text
