// Many nodes: every algorithm still gives the sequential renderer's picture on 64 and
// 128 nodes, and the communication self-test passes on 1024.
#include <gtest/gtest.h>

#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {
// A scene of the algorithm's paper, by the reference its speed-ups divide by.
std::string paper_scene(const Algorithm& a) {
  const std::string dir = std::string(ZCUBE_SOURCE_DIR) + "/scenes/";
  if (a.reference == "scanline") return dir + "kurc/1pot.json";
  if (a.reference == "node-initiated") return dir + "blazek/spheres_16.json";
  return dir + "teapot.json";
}
} // namespace

TEST(ManyNodes, EveryAlgorithmGivesTheSequentialImageOn64And128Nodes) {
  int ran = 0;
  for (int P : {64, 128})
    for (const Algorithm& a : algorithms()) {
      if (!a.draws_picture) continue; // pingpong, comm-check, the compositing study
      RunConfig c = sim_config("ipsc860", P, Topology::Cube, Fidelity::Circuit);
      c.algorithm = a.name;
      c.scene_path = paper_scene(a);
      c.width = c.height = 160; // partial strips: 2.5 and 1.25 rows a node
      c.compare_with_sequential = true;
      const auto r = run_simulation_isolated(c);
      ASSERT_EQ(r["status"], "ok") << a.name << " P=" << P << ": " << r.dump().substr(0, 400);
      EXPECT_EQ(r["image"]["identical_to_sequential"], true) << a.name << " P=" << P;
      ++ran;
    }
  EXPECT_GE(ran, 2 * 12); // elastic, Kurc's seven schemes, Blazek's four methods at least
}

TEST(ManyNodes, CommCheckPassesOn1024Nodes) {
  RunConfig c = sim_config("ipsc860", 1024, Topology::Cube, Fidelity::Analytic);
  c.algorithm = "comm-check";
  const auto r = run_simulation_isolated(c);
  ASSERT_EQ(r["status"], "ok") << r.dump().substr(0, 400);
  ASSERT_EQ(r["per_node"].size(), 1024u);
  for (const auto& n : r["per_node"]) {
    ASSERT_TRUE(n["metrics"].contains("comm_check_failures")) << n.dump();
    EXPECT_TRUE(n["metrics"]["comm_check_failures"].empty()) << n.dump();
  }
}
