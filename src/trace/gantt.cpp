#include "trace/gantt.hpp"

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

bool draw_gantt(const nlohmann::json& report, const std::string& path, const std::string& root) {
  check_gantt_path(path);
  if (!report.contains("timeline")) throw InputError(path, 0, "the report has no timeline to draw");
  // The script reads the timeline from a report file of its own (the user's --report may be
  // absent, or written only by rank 0 of an MPI job).
  const auto tmp = std::filesystem::temp_directory_path() /
                   ("zcube-" + std::to_string(getpid()) + "-gantt.json");
  std::ofstream(tmp) << report.dump();
  const bool ok = run_python_script(root, "scripts/plot_gantt.py", {tmp.string(), path});
  std::filesystem::remove(tmp);
  return ok;
}

} // namespace zc
