// repro/simulate: a batch sets up the triangles of a scene three or more of its points share once,
// in the process that forks them (raster/setup_cache.hpp); every point's report, virtual times and
// counters included, is the one of a simulation that sets up its triangles itself.
#include <gtest/gtest.h>

#include <cstdlib>

#include "raster/setup_cache.hpp"
#include "repro/simulate.hpp"
#include "sim/simulation.hpp"

using namespace zc;

namespace {

RunConfig point(const std::string& algorithm, const std::string& scene, int nodes) {
  RunConfig c;
  c.machine = "ipsc2";
  c.nodes = nodes;
  c.algorithm = algorithm;
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/" + scene;
  c.width = c.height = 128;
  return c;
}

// A report without what the host measured (its wall time and memory).
nlohmann::json modelled(nlohmann::json r) {
  r.erase("host");
  return r;
}

} // namespace

TEST(SimulateSetupCache, PointsReportAsIfEachSetUpItsOwnTriangles) {
  const std::string spheres = "blazek/thesis_spheres_4.json";
  std::vector<RunConfig> pts = {
      point("node-initiated", spheres, 2),    point("host-initiated", spheres, 4),
      point("object-forwarding", spheres, 4), point("host-broadcast", spheres, 8),
      point("elastic", "teapot.json", 4),     point("elastic", "teapot.json", 8),
      point("sequential", "teapot.json", 1)};
  pts[1].options.values["packet"] = "10";
  const auto reps = simulate_batch(pts, 2);
  ASSERT_EQ(reps.size(), pts.size());
  EXPECT_EQ(setup_cache_count(), 2u) << "the batch holds the set-up of both shared scenes";
  drop_setup_caches([](const Scene&) { return false; });
  for (std::size_t i = 0; i < pts.size(); ++i) {
    ASSERT_EQ(reps[i].value("status", ""), "ok") << reps[i].dump();
    const nlohmann::json alone = run_simulation_isolated(pts[i]);
    ASSERT_EQ(alone.value("status", ""), "ok") << alone.dump();
    EXPECT_EQ(reps[i]["virtual_time_s"], alone["virtual_time_s"]) << i;
    EXPECT_EQ(modelled(reps[i]), modelled(alone)) << i;
  }
}

// ZCUBE_SETUP_CACHE=0: no set-up is held, and a batch's reports are unchanged.
TEST(SimulateSetupCache, CanBeTurnedOff) {
  const std::vector<RunConfig> pts = {point("elastic", "teapot.json", 2),
                                      point("elastic", "teapot.json", 4),
                                      point("sequential", "teapot.json", 1)};
  const auto with = simulate_batch(pts, 2);
  EXPECT_EQ(setup_cache_count(), 1u);
  setenv("ZCUBE_SETUP_CACHE", "0", 1);
  const auto without = simulate_batch(pts, 2);
  unsetenv("ZCUBE_SETUP_CACHE");
  EXPECT_EQ(setup_cache_count(), 0u);
  ASSERT_EQ(with.size(), without.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    ASSERT_EQ(with[i].value("status", ""), "ok") << with[i].dump();
    EXPECT_EQ(modelled(with[i]), modelled(without[i])) << i;
  }
}
