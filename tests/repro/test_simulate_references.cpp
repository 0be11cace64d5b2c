// repro/simulate: a batch draws the sequential reference of a shared scene once, in the process
// that forks the simulations, and every point compares its image with it as it would with its own.
#include <gtest/gtest.h>

#include "repro/simulate.hpp"
#include "run/report.hpp"
#include "sim/simulation.hpp"

using namespace zc;

namespace {

RunConfig point(const std::string& algorithm, int nodes) {
  RunConfig c;
  c.machine = "ipsc860";
  c.nodes = nodes;
  c.algorithm = algorithm;
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";
  c.width = c.height = 96;
  return c;
}

} // namespace

// The batch's image sections equal those of simulations that draw their own reference.
TEST(SimulateReferences, BatchComparesAsEachSimulationAlone) {
  const std::vector<RunConfig> pts = {point("elastic", 4), point("elastic", 8),
                                      point("sequential", 1)};
  const auto reps = simulate_batch(pts, 2);
  ASSERT_EQ(reps.size(), pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    ASSERT_EQ(reps[i].value("status", ""), "ok") << reps[i].dump();
    EXPECT_EQ(reps[i]["nodes"], pts[i].nodes) << "reports in the points' order (run longest first)";
    EXPECT_EQ(reps[i]["image"]["identical_to_sequential"], true);
    EXPECT_EQ(reps[i]["image"], run_simulation_isolated(pts[i])["image"]) << i;
  }
}

// A run takes the reference its lookup gives: a wrong one is a difference.
TEST(SimulateReferences, ImageSectionUsesTheLookup) {
  ReferenceFrame wrong;
  wrong.sha256 = "not the picture";
  RunConfig looked_up = point("elastic", 4);
  looked_up.reference_lookup = [&](const Scene&, int, int) { return &wrong; };
  const auto rep = run_simulation_isolated(looked_up);
  EXPECT_EQ(rep["image"]["identical_to_sequential"], false);
  EXPECT_EQ(rep["image"]["differs_from_sequential"], "colour and depth");
  EXPECT_EQ(run_simulation_isolated(point("elastic", 4))["image"]["identical_to_sequential"], true);
}
