#pragma once
// Where zcube's data (scenes/, platforms/, scripts/, tests/golden/) is, in this order: the current
// directory when it is a zcube checkout; the installed tree beside the binary
// (<prefix>/bin/zcube -> <prefix>/share/zcube, `cmake --install`); the source tree this binary was
// built from (a build directory that was never installed).
#include <filesystem>
#include <string>
#include <system_error>

namespace zc::cli {

inline std::string source_root() {
  namespace fs = std::filesystem;
  if (fs::exists("scenes/teapot.json") && fs::exists("src/cli")) return ".";
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = (exe.parent_path() / ZCUBE_DATA_FROM_BIN).lexically_normal();
    if (fs::exists(installed / "scenes/teapot.json", ec)) return installed.string();
  }
  return ZCUBE_SOURCE_DIR;
}

// A data file named as in the checkout ("scenes/teapot.json", "platforms/ipsc2-16.xml",
// "tests/golden"): as given when it exists from the working directory (or is absolute), else the
// bundled one under source_root() when that exists, so the installed binary finds its scenes,
// platforms and golden runs from any directory. Anything else is returned as given (its error
// names it as the user wrote it).
inline std::string data_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty() || fs::path(path).is_absolute() || fs::exists(path, ec)) return path;
  const fs::path bundled = fs::path(source_root()) / path;
  return fs::exists(bundled, ec) ? bundled.string() : path;
}

// Whether the data comes from an installed tree (<prefix>/share/zcube), where nothing is written.
inline bool installed_data() {
  const std::string root = source_root();
  return root != "." && root != ZCUBE_SOURCE_DIR;
}

// The scene run, render and sweep use when none is given. It ships with the sources and the
// installed data; found from the working directory, else where the data is (source_root).
inline std::string default_scene_path() {
  const std::string rel = "scenes/teapot.json";
  if (std::filesystem::exists(rel)) return rel;
  return source_root() + "/" + rel;
}

} // namespace zc::cli
