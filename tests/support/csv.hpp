#pragma once
// Rows of a committed CSV file (results/) as maps from column name to cell, for tests that check
// a run against the tables zcube reproduce wrote.
#include <fstream>
#include <istream>
#include <map>
#include <string>
#include <vector>

namespace zc::test {

// RFC 4180 records: quoted cells may hold commas, doubled quotes and line breaks.
inline std::vector<std::vector<std::string>> csv_records(std::istream& in) {
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false, any = false;
  for (char c; in.get(c);) {
    any = true;
    if (quoted) {
      if (c != '"')
        cell += c;
      else if (in.peek() == '"')
        cell += char(in.get());
      else
        quoted = false;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.push_back(std::move(cell));
      cell.clear();
    } else if (c == '\n') {
      cells.push_back(std::move(cell));
      cell.clear();
      records.push_back(std::move(cells));
      cells.clear();
      any = false;
    } else if (c != '\r') {
      cell += c;
    }
  }
  if (any) {
    cells.push_back(std::move(cell));
    records.push_back(std::move(cells));
  }
  return records;
}

inline std::vector<std::map<std::string, std::string>> read_csv(const std::string& path) {
  std::ifstream f(path);
  std::vector<std::map<std::string, std::string>> rows;
  std::vector<std::string> header;
  for (auto& cells : csv_records(f)) {
    if (header.empty()) {
      header = std::move(cells);
      continue;
    }
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i)
      row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

// The cell `column` of the first row whose cells match every entry of `key`; empty if none.
inline std::string csv_cell(const std::string& path, const std::map<std::string, std::string>& key,
                            const std::string& column) {
  for (const auto& row : read_csv(path)) {
    bool match = true;
    for (const auto& [k, v] : key)
      match = match && row.count(k) && row.at(k) == v;
    if (match && row.count(column)) return row.at(column);
  }
  return "";
}

} // namespace zc::test
