#include "repro/gantt_chart.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "repro/plot_script.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

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
  // Each chart is drawn to a temporary file beside it and renamed into place once every chart is
  // drawn (util/output_file.hpp): a failed drawing leaves no partial picture.
  std::function<bool(std::size_t)> draw_from = [&](std::size_t i) {
    if (2 * i == args.size()) return run_python_script(root, "scripts/plot_gantt.py", args);
    write_file_atomically(args[2 * i + 1], [&](const std::string& tmp) {
      args[2 * i + 1] = tmp;
      return draw_from(i + 1);
    });
    return true;
  };
  bool ok = false;
  try {
    ok = draw_from(0);
  } catch (const std::runtime_error&) { // the script said why on stderr
  }
  std::filesystem::remove_all(dir);
  return ok;
}

} // namespace zc
