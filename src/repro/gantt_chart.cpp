#include "repro/gantt_chart.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "repro/plot_script.hpp"
#include "util/error.hpp"

namespace zc {

void check_gantt_path(const std::string& path) {
  for (const char* ext : {".png", ".svg", ".pdf"})
    if (path.size() > 4 && path.ends_with(ext)) return;
  throw UsageError("--gantt '" + path + "': expected a .png, .svg or .pdf file name");
}

bool draw_gantts(const std::vector<std::pair<const nlohmann::json*, std::string>>& charts,
                 const std::string& root) {
  // The script reads each timeline from a report file of its own (the user's --report may be
  // absent, or written only by rank 0 of an MPI job).
  const auto dir =
      std::filesystem::temp_directory_path() / ("zcube-" + std::to_string(getpid()) + "-gantt");
  std::filesystem::create_directories(dir);
  std::vector<std::string> args;
  for (std::size_t i = 0; i < charts.size(); ++i) {
    const auto& [report, path] = charts[i];
    check_gantt_path(path);
    if (!report->contains("timeline"))
      throw InputError(path, 0, "the report has no timeline to draw");
    const auto tmp = dir / (std::to_string(i) + ".json");
    std::ofstream(tmp) << report->dump();
    args.push_back(tmp.string());
    args.push_back(path);
  }
  const bool ok = run_python_script(root, "scripts/plot_gantt.py", args);
  std::filesystem::remove_all(dir);
  return ok;
}

} // namespace zc
