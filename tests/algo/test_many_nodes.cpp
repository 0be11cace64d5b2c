// Many nodes: every algorithm still gives the sequential renderer's picture on 64 and
// 128 nodes, and the communication self-test passes on 1024.
#include <gtest/gtest.h>

#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

TEST(ManyNodes, EveryAlgorithmGivesTheSequentialImageOn64And128Nodes) {
  const std::string dir = std::string(ZCUBE_SOURCE_DIR) + "/scenes/";
  const std::pair<const char*, const char*> cases[] = {
      {"elastic", "teapot.json"},
      {"zbuf-exc", "kurc/1pot.json"},
      {"pair-rs", "kurc/1pot.json"},
      {"pair-hbp", "kurc/1pot.json"},
      {"pair-even", "kurc/1pot.json"},
      {"aapc-rs", "kurc/1pot.json"},
      {"aapc-hbp", "kurc/1pot.json"},
      {"aapc-even", "kurc/1pot.json"},
      {"host-initiated", "blazek_fig9.sdl"},
      {"node-initiated", "blazek/spheres_16.json"},
      {"object-forwarding", "blazek/spheres_16.json"},
      {"host-broadcast", "blazek/spheres_16.json"}};
  for (int P : {64, 128})
    for (const auto& [algo, scene] : cases) {
      SimConfig c = sim_config("ipsc860", P, Topology::Cube, Fidelity::Circuit);
      c.algorithm = algo;
      c.scene_path = dir + scene;
      c.width = c.height = 160; // partial strips: 2.5 and 1.25 rows a node
      c.compare_with_sequential = true;
      const auto r = run_simulation_isolated(c);
      ASSERT_EQ(r["status"], "ok") << algo << " P=" << P << ": " << r.dump().substr(0, 400);
      EXPECT_EQ(r["image"]["identical_to_sequential"], true) << algo << " P=" << P;
    }
}

TEST(ManyNodes, CommCheckPassesOn1024Nodes) {
  SimConfig c = sim_config("ipsc860", 1024, Topology::Cube, Fidelity::Analytic);
  c.algorithm = "comm-check";
  const auto r = run_simulation_isolated(c);
  ASSERT_EQ(r["status"], "ok") << r.dump().substr(0, 400);
  ASSERT_EQ(r["per_node"].size(), 1024u);
  for (const auto& n : r["per_node"]) {
    ASSERT_TRUE(n["metrics"].contains("comm_check_failures")) << n.dump();
    EXPECT_TRUE(n["metrics"]["comm_check_failures"].empty()) << n.dump();
  }
}
