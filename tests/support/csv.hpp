#pragma once
// Rows of a committed CSV file (results/) as maps from column name to cell, for tests that check
// a run against the tables zcube reproduce wrote.
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace zc::test {

inline std::vector<std::map<std::string, std::string>> read_csv(const std::string& path) {
  std::ifstream f(path);
  std::vector<std::map<std::string, std::string>> rows;
  std::string line;
  std::vector<std::string> header;
  while (std::getline(f, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');)
      cells.push_back(c);
    if (line.ends_with(",")) cells.push_back("");
    if (header.empty()) {
      header = cells;
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
