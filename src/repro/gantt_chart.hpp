#pragma once
// Space-time diagrams (`zcube run --gantt`, `zcube reproduce`): ParaGraph-style charts of traced
// reports, drawn by scripts/plot_gantt.py (python3-matplotlib) from the reports' timelines.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace zc {

// UsageError (before any simulation) unless the extension is .png, .svg or .pdf.
void check_gantt_path(const std::string& path);
// Draws each (traced report, file) with one run of <root>/scripts/plot_gantt.py; false (with the
// script's message on stderr) when it could not.
bool draw_gantts(const std::vector<std::pair<const nlohmann::json*, std::string>>& charts,
                 const std::string& root);
inline bool draw_gantt(const nlohmann::json& report, const std::string& path,
                       const std::string& root) {
  return draw_gantts({{&report, path}}, root);
}

} // namespace zc
