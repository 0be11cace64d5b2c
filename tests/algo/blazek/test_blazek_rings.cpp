// algo/blazek: the hierarchical merge on rings of any size.

#include <gtest/gtest.h>

#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

TEST(Robustness, BlazekMergeOnRingsOfAnySize) {
  // The hierarchical merge (Algorithm 4) on node counts that are not powers of two.
  for (const char* algo : {"host-initiated", "node-initiated"})
    for (int P : {3, 6}) {
      RunConfig c = sim_config("ipsc2", P, Topology::Ring, Fidelity::Circuit);
      c.algorithm = algo;
      c.width = c.height = 48;
      c.compare_with_sequential = true;
      c.what_ifs.set("memory", {64.0 * 1024 * 1024});
      c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/blazek/spheres_16.json";
      auto r = run_simulation_isolated(c);
      ASSERT_EQ(r.value("status", ""), "ok") << algo << " P=" << P << ": " << r.dump();
      EXPECT_TRUE(r["image"]["identical_to_sequential"].get<bool>()) << algo << " P=" << P;
    }
}
