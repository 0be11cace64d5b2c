#pragma once
// The figures the papers print (docs/index.md cites them), as data: the calibration's targets and
// the paper column of reports and of `zcube reproduce`. Held-out figures are not here, by design.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace zc {

// Kurc, Aykanat, Ozguc, Table 2: P = 16, 400x400, iPSC/2; ms per phase.
struct KurcPhaseFigure {
  std::string scene;  // 1pot, 2pot, 4pot_1, 4pot_2, 8pot_1, 8pot_2 (scenes/kurc/<scene>.json)
  std::string scheme; // pair-rs, zbuf-exc
  std::string phase;  // span_list_creation, local_zbuffer, pixel_merging
  double ms;
};
const std::vector<KurcPhaseFigure>& kurc_table2_p16();
const std::vector<std::string>& kurc_scenes();
const std::vector<std::string>& kurc_phases();
constexpr int kKurcTableNodes = 16, kKurcTableSize = 400;

// Charles, Lefevre, Miguet §6: speed-up of the elastic z-buffer on the teapot, hypercube. The
// paper does not state the picture size of these two figures; zcube takes 512x512, the size whose
// speed-ups the text says are the better ones ("the bigger the picture size is, the better").
struct CharlesSpeedupFigure {
  int nodes;
  double speedup;
};
const std::vector<CharlesSpeedupFigure>& charles_teapot_speedups();
constexpr int kCharlesTeapotSize = 512;
// Charles et al.'s teapot (§5-§6): Newell's patches framed so that Table 1 is matched
// (scripts/charles_scenes.py, scenes/README.md), relative to the repository root.
constexpr const char* kCharlesTeapotScene = "scenes/charles/teapot.json";

// The paper figures a run corresponds to (empty when none): a list of
// {"source", "quantity", "phase"?, "paper", "predicted"?, "rel_error"?}. Matching is on
// algorithm, machine, node count, topology, image size and scene file (scenes/kurc/<name>.json,
// scenes/charles/teapot.json). `sequential_time_s`, when given, completes the speed-up figures.
nlohmann::json paper_figures_for(const nlohmann::json& report,
                                 std::optional<double> sequential_time_s = std::nullopt);
// What a paper figure is matched on, known before a run.
struct PaperRun {
  std::string algorithm, machine, topology, scene_path;
  int nodes = 0;
};
// True when the run matches a speed-up figure, whose prediction needs the sequential time.
// `picture_size` (width, height) is called only when everything else matches: it may load the
// scene.
bool needs_sequential_time(const PaperRun& run,
                           const std::function<std::pair<int, int>()>& picture_size);

} // namespace zc
