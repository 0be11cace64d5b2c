// repro/paper_figures: a run's report gets the papers' figures it can be compared with.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "csv.hpp"
#include "machine/cpu_model.hpp"
#include "machine/machine.hpp"
#include "repro/paper_figures.hpp"
#include "repro/regress.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"
#include "repro/sweep.hpp"
#include "source_root.hpp"
#include "util/error.hpp"
#include "util/nnls.hpp"

using namespace zc;

namespace {

using test::kRoot;

using test::read_csv;

} // namespace

TEST(PaperFigures, AKurcRunGetsItsThreeTable2FiguresWithTheirErrors) {
  nlohmann::json r = {
      {"status", "ok"},
      {"algorithm", "pair-rs"},
      {"machine", "ipsc2"},
      {"topology", "cube"},
      {"nodes", 16},
      {"virtual_time_s", 2.0},
      {"scene", {{"path", "/x/scenes/kurc/1pot.json"}, {"width", 400}, {"height", 400}}},
      {"phases",
       {{{"name", "span_list_creation"}, {"max_s", 0.322}},
        {{"name", "local_zbuffer"}, {"max_s", 0.868}},
        {{"name", "pixel_merging"}, {"max_s", 0.174}}}}};
  const auto f = paper_figures_for(r);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_NEAR(f[0]["rel_error"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(f[1]["rel_error"].get<double>(), 1.0, 1e-12);  // 868 against 434
  EXPECT_NEAR(f[2]["rel_error"].get<double>(), -0.5, 1e-12); // 174 against 348
  r["nodes"] = 8;                                            // held out: no figure
  EXPECT_TRUE(paper_figures_for(r).empty());
  r["nodes"] = 16;
  r["scene"]["width"] = 640;
  EXPECT_TRUE(paper_figures_for(r).empty());
}

TEST(PaperFigures, CharlesSpeedupNeedsTheSequentialTime) {
  nlohmann::json r = {{"status", "ok"},
                      {"algorithm", "elastic"},
                      {"machine", "ipsc860"},
                      {"topology", "cube"},
                      {"nodes", 16},
                      {"virtual_time_s", 1.0},
                      {"phases", nlohmann::json::array()},
                      {"scene", {{"path", kCharlesTeapotScene}, {"width", 512}, {"height", 512}}}};
  int size_asked = 0;
  const auto size = [&size_asked](int n) {
    return [&size_asked, n] {
      ++size_asked;
      return std::pair{n, n};
    };
  };
  PaperRun run{"elastic", "ipsc860", "cube", kCharlesTeapotScene, 16};
  EXPECT_TRUE(needs_sequential_time(run, size(512)));
  EXPECT_FALSE(needs_sequential_time(run, size(256)));
  EXPECT_EQ(size_asked, 2);
  // The default teapot is not the paper's (Table 1 frames Charles's): no figure, and no size
  // asked for (no scene loaded).
  run.scene_path = "scenes/teapot.json";
  EXPECT_FALSE(needs_sequential_time(run, size(512)));
  run.scene_path = kCharlesTeapotScene;
  run.algorithm = "sequential";
  EXPECT_FALSE(needs_sequential_time(run, size(512)));
  EXPECT_EQ(size_asked, 2);
  auto f = paper_figures_for(r);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_FALSE(f[0].contains("predicted"));
  f = paper_figures_for(r, 8.3 * 1.1);
  EXPECT_NEAR(f[0]["rel_error"].get<double>(), 0.1, 1e-12);
  r["topology"] = "ring";
  EXPECT_TRUE(paper_figures_for(r).empty());
}

// A what-if run still gets the paper's figure to compare with, marked as not the paper's machine.
TEST(PaperFigures, AWhatIfRunsFiguresAreMarked) {
  nlohmann::json r = {
      {"status", "ok"},
      {"machine", "ipsc860"},
      {"topology", "cube"},
      {"nodes", 16},
      {"algorithm", "elastic"},
      {"virtual_time_s", 1.0},
      {"phases", nlohmann::json::array()},
      {"what_if", nlohmann::json::object()},
      {"scene", {{"path", kRoot + "/" + kCharlesTeapotScene}, {"width", 512}, {"height", 512}}}};
  auto f = paper_figures_for(r, 8.3);
  ASSERT_EQ(f.size(), 1u) << r.dump();
  EXPECT_FALSE(f[0].contains("what_if"));
  r["what_if"]["cpu_scale"] = 2.0;
  f = paper_figures_for(r, 8.3);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0]["what_if"], true);
}
