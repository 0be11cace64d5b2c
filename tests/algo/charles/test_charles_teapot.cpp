// Charles, Lefevre, Miguet 1995, §5 Table 1: the teapot stand-in (scenes/charles/teapot.json,
// written by scripts/charles_scenes.py) and the elastic cut zcube computes on it, 256x256 on four
// iPSC/860 nodes. The bounds are the residuals documented in scenes/README.md, with a little room.
#include <cmath>
#include <cstdlib>

#include <gtest/gtest.h>

#include "repro/paper_figures.hpp"
#include "scene/load.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

const std::string kScene = std::string(ZCUBE_SOURCE_DIR) + "/" + kCharlesTeapotScene;

struct Row {
  int triangles, rows;
};
// Table 1: number of triangles and number of rows per processor.
const Row kTable1[] = {{1304, 63}, {1056, 21}, {822, 22}, {1056, 149}};

nlohmann::json table1_run() {
  RunConfig c = sim_config("ipsc860", 4, Topology::Cube, Fidelity::Circuit);
  c.algorithm = "elastic";
  c.scene_path = kScene;
  c.width = c.height = 256;
  c.compare_with_sequential = false;
  return run_simulation_isolated(c);
}

} // namespace

TEST(CharlesTeapot, CountsWithinOnePercentOfThePapers) {
  const Scene s = load_scene(kScene);
  EXPECT_EQ(s.triangles.size(), 3552u);
  EXPECT_EQ(s.vertices.size(), 1953u);
  EXPECT_LT(std::fabs(double(s.triangles.size()) - 3572.0) / 3572.0, 0.01);
  EXPECT_LT(std::fabs(double(s.vertices.size()) - 1970.0) / 1970.0, 0.01);
  EXPECT_EQ(s.width, 256);
  EXPECT_EQ(s.height, 256);
}

TEST(CharlesTeapot, Table1CutWithinTheDocumentedResiduals) {
  const auto a = table1_run(), b = table1_run();
  ASSERT_EQ(a["status"], "ok") << a.dump();
  const auto& slices = a["elastic"]["slices"];
  EXPECT_EQ(slices, b["elastic"]["slices"]); // the same cut, bit for bit
  ASSERT_EQ(slices.size(), 4u);
  int rows = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& s = slices[k];
    const int r = s["rows"].get<int>(), t = s["triangles"].get<int>();
    rows += r;
    EXPECT_LE(std::abs(r - kTable1[k].rows), 3) << "node " << k + 1 << " rows " << r;
    EXPECT_LT(std::fabs(t - kTable1[k].triangles) / kTable1[k].triangles, 0.15)
        << "node " << k + 1 << " triangles " << t;
    EXPECT_NEAR(s["work_percent"].get<double>(), 25.0, 1.5) << "node " << k + 1;
  }
  EXPECT_EQ(rows, 256);
}
