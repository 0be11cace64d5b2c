#pragma once
// How a report's bands and sensitivities read in a terminal (`zcube run --bands --sensitivity`),
// and the tornado plot of the sensitivities (scripts/plot_tornado.py).
#include <string>

#include <nlohmann/json.hpp>

namespace zc {

// "90 % band 0.51 .. 0.58 s (p50 0.54)".
std::string band_text(const nlohmann::json& band);
// The bands of the virtual time and the timed region, how the draws were priced, and the five
// largest elasticities of the timed region (or of the whole run when none is marked).
std::string bands_and_sensitivity_text(const nlohmann::json& report);
// UsageError (before any simulation) unless the extension is .png, .svg or .pdf.
void check_tornado_path(const std::string& path);
// The elasticities of the timed region as a tornado plot; false (the script's message on stderr)
// when it could not be drawn.
bool draw_tornado(const nlohmann::json& report, const std::string& path, const std::string& root);

} // namespace zc
