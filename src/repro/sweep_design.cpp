#include "repro/sweep_design.hpp"

#include <algorithm>
#include <fstream>
#include <set>

#include "run/run_flags.hpp"
#include "scene/load.hpp"
#include "sim/platform_load.hpp"
#include "util/error.hpp"

namespace zc {

std::vector<SweepPoint> expand_one_at_a_time(const std::vector<SweepAxis>& axes,
                                             const std::string& scene, const Locate& locate) {
  std::map<std::string, std::string> base;
  for (const auto& ax : axes)
    base[ax.flag] = ax.values.front();
  std::vector<SweepPoint> pts = {make_point(base, scene, locate)};
  for (const auto& ax : axes)
    for (std::size_t i = 1; i < ax.values.size(); ++i) {
      auto values = base;
      values[ax.flag] = ax.values[i];
      pts.push_back(make_point(values, scene, locate));
    }
  return pts;
}

namespace {

// One line of a point file split at its commas (no quoting: flag values hold no commas).
std::vector<std::string> cells_of(const std::string& line, const std::string& path, int n) {
  if (line.find('"') != std::string::npos)
    throw InputError(path, n, "quoted cells are not read (no flag value holds a comma)");
  std::vector<std::string> cells;
  std::size_t a = 0;
  while (true) {
    const std::size_t b = line.find(',', a);
    std::string c = line.substr(a, b == std::string::npos ? std::string::npos : b - a);
    c.erase(0, c.find_first_not_of(" \t"));
    c.erase(c.find_last_not_of(" \t\r") + 1);
    cells.push_back(c);
    if (b == std::string::npos) return cells;
    a = b + 1;
  }
}

std::vector<SweepAxis> header_axes(const std::vector<std::string>& header,
                                   const std::string& path) {
  std::vector<SweepAxis> axes;
  for (const auto& h : header) {
    if (!find_run_flag(h))
      throw InputError(path, 1, "'" + h + "' is not a zcube run flag (e.g. nodes, latency)");
    for (const auto& ax : axes)
      if (ax.flag == h) throw InputError(path, 1, "the flag '" + h + "' appears twice");
    axes.push_back({h, {}});
  }
  if (axes.empty()) throw InputError(path, 1, "expected a header of zcube run flags");
  return axes;
}

} // namespace

PointFile read_point_file(const std::string& path, const std::string& scene, const Locate& locate) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot read the point file");
  std::string line;
  PointFile f;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto cells = cells_of(line, path, n);
    if (f.axes.empty()) {
      f.axes = header_axes(cells, path);
      continue;
    }
    if (cells.size() != f.axes.size())
      throw InputError(path, n,
                       std::to_string(cells.size()) + " cells, the header has " +
                           std::to_string(f.axes.size()));
    std::map<std::string, std::string> values;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      values[f.axes[i].flag] = cells[i];
      auto& seen = f.axes[i].values;
      if (std::find(seen.begin(), seen.end(), cells[i]) == seen.end()) seen.push_back(cells[i]);
    }
    f.points.push_back(make_point(values, scene, locate));
  }
  if (f.points.empty()) throw InputError(path, n, "no points (a header, then a row a point)");
  return f;
}

void check_point_inputs(const std::vector<SweepPoint>& points) {
  std::set<std::string> scenes, platforms;
  for (const auto& p : points)
    if (p.config) {
      scenes.insert(p.config->scene_path);
      if (is_platform_file(p.config->machine)) platforms.insert(p.config->machine);
    }
  for (const auto& s : scenes)
    load_scene(s); // InputError naming the file (and line) when missing or malformed
  for (const auto& m : platforms)
    check_platform_file(m);
}

} // namespace zc
