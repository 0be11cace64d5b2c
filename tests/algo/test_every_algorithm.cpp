// Every registered algorithm on 4 nodes, small scene and image: a correct run whose image equals
// the sequential renderer's (comm-check: every collective and message order checked, no failure).
// The same file is built into test_sim_asan (CMakeLists.txt) with the simulator under
// AddressSanitizer + UndefinedBehaviorSanitizer. There SimGrid runs its actors on
// threads (contexts/factory:thread): its default context switching moves between stacks that ASan
// does not know about (with ASan's stack-use-after-return check on, raw, boost and ucontext
// contexts all give false stack-buffer-overflows; threads none).
#include <gtest/gtest.h>

#include "algo/algorithm.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

RunConfig four_nodes(const std::string& algorithm) {
  RunConfig c = sim_config("ipsc2", 4, Topology::Cube, Fidelity::Circuit);
  c.algorithm = algorithm;
  c.width = 24;
  c.height = 20; // not a multiple of 4: partial strips and bands
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/blazek/spheres_16.json";
  c.what_ifs.set("memory", {64.0 * 1024 * 1024});
  // Every algorithm that draws a picture (not comm-check, pingpong, compositing-study).
  c.compare_with_sequential = algorithm != "comm-check" && find_algorithm(algorithm).draws_picture;
#ifdef ZCUBE_SANITIZED
  c.simgrid_args = {"--cfg=contexts/factory:thread"};
#endif
  return c;
}

} // namespace

TEST(EveryAlgorithm, FourNodesRunAndMatchTheSequentialImage) {
  ASSERT_GE(algorithms().size(), 16u);
  for (const Algorithm& a : algorithms()) {
    SCOPED_TRACE(a.name);
    RunConfig c = four_nodes(a.name);
    if (a.name == "pingpong") c.options.values = {{"sizes", "16B,1KiB"}, {"from", "0"}};
    const auto r = run_simulation_isolated(c);
    ASSERT_EQ(r.value("status", ""), "ok") << r.dump().substr(0, 600);
    EXPECT_GT(r.value("virtual_time_s", 0.0), 0.0);
    if (a.name == "comm-check") {
      ASSERT_TRUE(r.contains("comm_check_failures"));
      EXPECT_TRUE(r["comm_check_failures"].empty()) << r["comm_check_failures"].dump();
    }
    if (c.compare_with_sequential && a.draws_picture) { // compositing-study draws none
      EXPECT_TRUE(r["image"]["identical_to_sequential"].get<bool>());
    }
  }
}

TEST(EveryAlgorithm, FailedRunsEndCleanly) {
  // The failure paths under the sanitizers too: a node out of memory kills every actor mid-run,
  // and a deadlock leaves actors blocked when the simulation ends.
  // Peaks at this size: elastic 1.03 MB, zbuf-exc 1.75 MB, host-initiated 0.534 MB a node.
  for (const auto& [name, memory] : {std::pair{"elastic", 1.0e6}, std::pair{"zbuf-exc", 1.5e6},
                                     std::pair{"host-initiated", 0.53e6}}) {
    SCOPED_TRACE(name);
    RunConfig c = four_nodes(name);
    c.what_ifs.set("memory", {memory});
    const auto r = run_simulation_isolated(c);
    EXPECT_EQ(r.value("status", ""), "out_of_memory") << r.dump().substr(0, 600);
  }
  RunConfig c = four_nodes("sequential");
  c.compare_with_sequential = false;
  const auto r = run_custom(c, [](NodeContext& ctx) {
    if (ctx.rank() == 1) ctx.comm().recv(2, 9);
  });
  EXPECT_EQ(r.value("status", ""), "error");
  EXPECT_NE(r.value("error", "").find("deadlock"), std::string::npos) << r.dump();
}
