#include "repro/band_text.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <vector>

#include "repro/plot_script.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

namespace zc {

std::string band_text(const nlohmann::json& band) {
  std::ostringstream s;
  s << std::setprecision(4) << "90 % band " << band.at("p05").get<double>() << " .. "
    << band.at("p95").get<double>() << " s (p50 " << band.at("p50").get<double>() << ")";
  return s.str();
}

namespace {

// The figure the sensitivities are printed for: the timed region when the run marks one.
const char* sensitivity_quantity(const nlohmann::json& s) {
  return s.contains("timed_s") ? "timed_s" : "virtual_time_s";
}

std::string sensitivity_text(const nlohmann::json& s) {
  std::ostringstream o;
  if (s.value("method", "") == "unavailable") {
    o << "sensitivity: unavailable (" << s.value("why", "") << ")\n";
    return o.str();
  }
  const char* q = sensitivity_quantity(s);
  if (!s.contains(q)) return "";
  std::vector<std::pair<std::string, double>> e;
  for (const auto& [name, v] : s[q].items())
    e.emplace_back(name, v.get<double>());
  std::stable_sort(e.begin(), e.end(), [](const auto& a, const auto& b) {
    return std::abs(a.second) > std::abs(b.second);
  });
  o << "sensitivity of " << q << " (d ln T / d ln theta), the five largest:\n";
  for (std::size_t i = 0; i < e.size() && i < 5; ++i)
    o << "  " << std::left << std::setw(28) << e[i].first << std::showpos << std::fixed
      << std::setprecision(3) << e[i].second << std::noshowpos << std::defaultfloat << "\n";
  return o.str();
}

} // namespace

std::string bands_and_sensitivity_text(const nlohmann::json& j) {
  std::ostringstream o;
  if (j.contains("bands")) {
    const auto& b = j["bands"];
    if (b.value("method", "") == "unavailable") {
      o << "bands: unavailable (" << b.value("why", "") << ")\n";
    } else {
      o << "bands: " << b["draws"].get<int>() << " draws of the uncertainty model ("
        << b["method"].get<std::string>() << (b.contains("why_simulated") ? ": " : "")
        << b.value("why_simulated", "") << "), virtual time " << band_text(b["virtual_time_s"]);
      if (b.contains("timed_s")) o << ", timed region " << band_text(b["timed_s"]);
      o << "\n";
      if (b.value("reordered_draws", 0) > 0)
        o << "  " << b["reordered_draws"].get<int>()
          << " draws kept a receive from any source in its recorded order although another "
             "sender's message came first under them (an approximation: docs/uncertainty.md)\n";
      if (b.value("failed_draws", 0) > 0)
        o << "  " << b["failed_draws"].get<int>()
          << " draws left out: out of node memory under them\n";
    }
  }
  if (j.contains("sensitivity")) o << sensitivity_text(j["sensitivity"]);
  return o.str();
}

void check_tornado_path(const std::string& path) {
  for (const char* ext : {".png", ".svg", ".pdf"})
    if (path.size() > 4 && path.ends_with(ext)) return;
  throw UsageError("--sensitivity-plot '" + path + "': expected a .png, .svg or .pdf file name");
}

bool draw_tornado(const nlohmann::json& report, const std::string& path, const std::string& root) {
  if (!report.contains("sensitivity") || report["sensitivity"].value("method", "") != "retimed")
    throw InputError(path, 0, "the run has no sensitivities to draw");
  const auto tmp_json = std::filesystem::temp_directory_path() /
                        ("zcube-" + std::to_string(getpid()) + "-tornado.json");
  std::ofstream(tmp_json) << report.dump();
  bool ok = false;
  try {
    write_file_atomically(path, [&](const std::string& tmp) {
      ok = run_python_script(
          root, "scripts/plot_tornado.py",
          {tmp_json.string(), tmp, std::filesystem::path(path).extension().string().substr(1)});
      return ok;
    });
  } catch (const std::runtime_error&) { // the script said why on stderr
    ok = false;
  }
  std::filesystem::remove(tmp_json);
  return ok;
}

} // namespace zc
