#include "repro/paper_figures.hpp"

#include <cmath>
#include <filesystem>
#include <functional>

#include "repro/reproduce.hpp"

namespace zc {

const std::vector<std::string>& kurc_scenes() {
  static const std::vector<std::string> s = {"1pot",   "2pot",   "4pot_1",
                                             "4pot_2", "8pot_1", "8pot_2"};
  return s;
}

const std::vector<std::string>& kurc_phases() {
  static const std::vector<std::string> p = {"span_list_creation", "local_zbuffer",
                                             "pixel_merging"};
  return p;
}

const std::vector<KurcPhaseFigure>& kurc_table2_p16() {
  static const std::vector<KurcPhaseFigure> t = [] {
    // Table 2, P = 16 rows: PAIR-RS then ZBUF-EXC, three phases each (ms).
    const struct {
      const char* scene;
      double pair[3], zbuf[3];
    } rows[] = {{"1pot", {322, 434, 348}, {316, 578, 2015}},
                {"2pot", {481, 471, 341}, {470, 585, 1940}},
                {"4pot_1", {1038, 520, 323}, {1015, 647, 1930}},
                {"4pot_2", {1124, 579, 408}, {1099, 702, 1958}},
                {"8pot_1", {2142, 1079, 684}, {2104, 1128, 2043}},
                {"8pot_2", {2087, 701, 451}, {2029, 805, 1958}}};
    std::vector<KurcPhaseFigure> v;
    for (const auto& r : rows)
      for (int s = 0; s < 2; ++s)
        for (int p = 0; p < 3; ++p)
          v.push_back({r.scene, s == 0 ? "pair-rs" : "zbuf-exc", kurc_phases()[std::size_t(p)],
                       s == 0 ? r.pair[p] : r.zbuf[p]});
    return v;
  }();
  return t;
}

const std::vector<CharlesSpeedupFigure>& charles_teapot_speedups() {
  static const std::vector<CharlesSpeedupFigure> f = {{8, 5.6}, {16, 8.3}};
  return f;
}

namespace {

std::string scene_key(const std::string& path) {
  const std::filesystem::path p(path);
  return p.parent_path().filename().string() + "/" + p.stem().string();
}

std::string scene_key(const nlohmann::json& report) {
  return scene_key(report["scene"].value("path", ""));
}

bool is(const nlohmann::json& r, const char* key, const std::string& v) {
  return r.contains(key) && r[key].is_string() && r[key].get<std::string>() == v;
}

bool sized(const nlohmann::json& r, int n) {
  return r["scene"].value("width", 0) == n && r["scene"].value("height", 0) == n;
}

// Charles et al.'s speed-up figure of the run, when it is one of theirs; the picture size is
// asked for last (it may mean loading the scene).
const CharlesSpeedupFigure* charles_match(const PaperRun& r,
                                          const std::function<std::pair<int, int>()>& size) {
  if (r.algorithm != "elastic" || r.machine != "ipsc860" || r.topology != "cube" ||
      scene_key(r.scene_path) != "charles/teapot")
    return nullptr;
  const CharlesSpeedupFigure* match = nullptr;
  for (const auto& f : charles_teapot_speedups())
    if (r.nodes == f.nodes) match = &f;
  if (!match) return nullptr;
  const auto [w, h] = size();
  return w == kCharlesTeapotSize && h == kCharlesTeapotSize ? match : nullptr;
}

const CharlesSpeedupFigure* charles_match(const nlohmann::json& r) {
  if (!r.contains("scene")) return nullptr;
  const PaperRun run{r.value("algorithm", ""), r.value("machine", ""), r.value("topology", ""),
                     r["scene"].value("path", ""), r.value("nodes", 0)};
  return charles_match(run, [&r] {
    return std::pair{r["scene"].value("width", 0), r["scene"].value("height", 0)};
  });
}

double rel_error(double predicted, double paper) {
  return (predicted - paper) / paper;
}

} // namespace

bool needs_sequential_time(const PaperRun& run,
                           const std::function<std::pair<int, int>()>& picture_size) {
  return charles_match(run, picture_size) != nullptr;
}

nlohmann::json paper_figures_for(const nlohmann::json& r, std::optional<double> seq_s) {
  nlohmann::json out = nlohmann::json::array();
  if (!r.contains("scene") || r.value("status", "") != "ok") return out;
  if (is(r, "machine", "ipsc2") && is(r, "topology", "cube") &&
      r.value("nodes", 0) == kKurcTableNodes && sized(r, kKurcTableSize)) {
    for (const auto& f : kurc_table2_p16()) {
      if (!is(r, "algorithm", f.scheme) || scene_key(r) != "kurc/" + f.scene) continue;
      nlohmann::json e = {{"source", "Kurc, Aykanat, Ozguc, Table 2"},
                          {"quantity", "phase_ms"},
                          {"phase", f.phase},
                          {"paper", f.ms}};
      for (const auto& p : r["phases"])
        if (p["name"] == f.phase) {
          const double ms = p["max_s"].get<double>() * 1e3;
          e["predicted"] = ms;
          e["rel_error"] = rel_error(ms, f.ms);
        }
      out.push_back(e);
    }
  }
  if (const CharlesSpeedupFigure* f = charles_match(r)) {
    nlohmann::json e = {{"source", "Charles, Lefevre, Miguet 1995, section 6 (teapot, hypercube)"},
                        {"quantity", "speedup"},
                        {"paper", f->speedup}};
    if (seq_s) {
      const double s = *seq_s / timed_s(r); // the paper's timed region (docs/papers.md)
      e["predicted"] = s;
      e["rel_error"] = rel_error(s, f->speedup);
    }
    out.push_back(e);
  }
  // A what-if run is compared with the paper too, but is not the paper's machine: say so.
  if (r.contains("what_if") && r["what_if"].is_object() && !r["what_if"].empty())
    for (auto& e : out)
      e["what_if"] = true;
  return out;
}

} // namespace zc
