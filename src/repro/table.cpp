#include "repro/table.hpp"

#include "util/output_file.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace zc {

namespace {

// RFC 4180: a cell holding a comma, a quote or a line break (CR or LF) is quoted, its quotes
// doubled.
std::string quote(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  q += '"';
  return q;
}

std::string line(const std::vector<std::string>& cells) {
  std::string l;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i) l += ',';
    l += quote(cells[i]);
  }
  l += '\n';
  return l;
}

// A Markdown table cell: a '|' would end the cell, a line break the row.
std::string md_cell(const std::string& s) {
  std::string c;
  for (char ch : s) {
    if (ch == '|')
      c += "\\|";
    else if (ch == '\n' || ch == '\r')
      c += ' ';
    else
      c += ch;
  }
  return c;
}

} // namespace

std::string Table::csv() const {
  std::string s = line(header);
  for (const auto& r : rows)
    s += line(r);
  return s;
}

std::string Table::markdown() const {
  std::string s = "|";
  for (const auto& h : header) {
    s += ' ';
    s += md_cell(h);
    s += " |";
  }
  s += "\n|";
  for (std::size_t i = 0; i < header.size(); ++i)
    s += "---|";
  s += "\n";
  for (const auto& r : rows) {
    s += "|";
    for (const auto& c : r) {
      s += ' ';
      s += md_cell(c);
      s += " |";
    }
    s += "\n";
  }
  return s;
}

void write_text(const std::string& path, const std::string& text) {
  const std::filesystem::path p(path);
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  write_text_file(path, text); // atomically (util/output_file.hpp)
}

void Table::write_csv(const std::string& path) const {
  write_text(path, csv());
}

std::string num(double v, int digits) {
  std::ostringstream s;
  // A count or a byte size is an integer: 112853000, never 1.12853e+08 (which reads as a rounded
  // float). 2^53 is where a double stops holding every integer.
  if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 9007199254740992.0)
    s << std::fixed << std::setprecision(0) << v;
  else
    s << std::setprecision(digits) << v;
  return s.str();
}

std::string fixed(double v, int decimals) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << v;
  return s.str();
}

std::string percent(double rel) {
  std::ostringstream s;
  s << std::showpos << std::fixed << std::setprecision(1) << 100 * rel << " %";
  return s.str();
}

} // namespace zc
