#pragma once
// `zcube run --gantt FILE.png|.svg|.pdf`: a ParaGraph-style space-time diagram of a traced report,
// drawn by scripts/plot_gantt.py (python3-matplotlib) from the report's timeline.
#include <string>

#include <nlohmann/json.hpp>

namespace zc {

// UsageError (before any simulation) unless the extension is .png, .svg or .pdf.
void check_gantt_path(const std::string& path);
// Draws the chart with <root>/scripts/plot_gantt.py; false (with the script's message on stderr)
// when it could not.
bool draw_gantt(const nlohmann::json& report, const std::string& path, const std::string& root);

} // namespace zc
