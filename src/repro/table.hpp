#pragma once
// A table of strings written as CSV (RFC 4180 quoting) or as a Markdown table: the results files
// of `zcube reproduce` and `zcube sweep`.
#include <string>
#include <vector>

namespace zc {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  void add(std::vector<std::string> row) { rows.push_back(std::move(row)); }
  std::string csv() const;
  std::string markdown() const;
  void write_csv(const std::string& path) const; // throws std::runtime_error when it cannot
};

// Numbers as the results files print them: `digits` significant digits, no trailing noise, and an
// integral value as the integer it is (no exponent).
std::string num(double v, int digits = 6);
// Fixed decimals (times in ms).
std::string fixed(double v, int decimals);
// A relative error as a signed percentage ("+3.2 %"): for README prose and tables only; a CSV
// holds the fraction (num).
std::string percent(double rel);

void write_text(const std::string& path, const std::string& text);

} // namespace zc
