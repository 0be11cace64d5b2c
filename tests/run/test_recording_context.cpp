// run/recording_context: phases, modelled node memory (exceeding it fails and says where and by
// how much) and the report keys a run falls back to.
#include <bit>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <unistd.h>

#include <gtest/gtest.h>
#include <simgrid/s4u.hpp>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "machine/topology.hpp"
#include "machine/units.hpp"
#include "sim_fixtures.hpp"
#include "util/error.hpp"

using namespace zc;
using namespace zc::test;

TEST(NodeContext, PhasesMemoryAndFallbackReportKeys) {
  auto r =
      run_custom(sim_config("ipsc2", 4, Topology::Cube, Fidelity::Circuit), [](NodeContext& ctx) {
        {
          auto ph = ctx.phase("work");
          Counters c;
          c.spans = 1000 * std::uint64_t(ctx.rank() + 1);
          ctx.charge(c);
        }
        ctx.alloc(1000.0 * (ctx.rank() + 1), "buffer");
        ctx.release(1000.0 * (ctx.rank() + 1));
        ctx.alloc(10, "small");
        if (ctx.rank() == 1) ctx.comm().send(0, 0, Bytes(777));
        if (ctx.rank() == 0) ctx.comm().recv(1, 0);
      });
  ASSERT_EQ(r["status"], "ok") << r.dump();
  const double span = machine_spec("ipsc2").cost.spans;
  ASSERT_EQ(r["phases"].size(), 1u);
  expect_rel(r["phases"][0]["max_s"].get<double>(), 4000 * span, 1e-12, "phase max");
  expect_rel(r["phases"][0]["min_s"].get<double>(), 1000 * span, 1e-12, "phase min");
  expect_rel(r["phases"][0]["mean_s"].get<double>(), 2500 * span, 1e-12, "phase mean");
  // The node operating system is resident before the algorithm's first buffer.
  const double os = machine_spec("ipsc2").os_resident_bytes;
  ASSERT_GT(os, 0);
  for (int k = 0; k < 4; ++k)
    EXPECT_EQ(r["per_node"][k]["peak_memory_bytes"].get<double>(), os + 1000.0 * (k + 1));
  // Report keys present even when the algorithm does not refine them.
  EXPECT_EQ(r["communication"]["concurrent_volume_bytes"], 777);
  expect_rel(r["load_imbalance"].get<double>(), 3000.0 / 2500.0, 1e-12, "busy imbalance");
  for (const char* k : {"machine", "platform", "nodes", "topology", "fidelity", "algorithm",
                        "scene", "virtual_time_s", "phases", "per_node", "communication",
                        "load_imbalance", "counters", "image", "host"})
    EXPECT_TRUE(r.contains(k)) << k;
  EXPECT_TRUE(r["host"].contains("wall_time_s"));
}

TEST(Memory, ExceedingNodeMemoryFailsAndSaysWhereAndByHowMuch) {
  RunConfig c = sim_config("ipsc2", 1, Topology::Cube, Fidelity::Circuit);
  c.algorithm = "sequential";
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";
  c.width = c.height = 1024; // 7 bytes a pixel (depth and colour): 7.3 MB > 4 MB
  auto r = run_simulation_isolated(c);
  EXPECT_EQ(r["status"], "out_of_memory");
  const std::string e = r["error"];
  EXPECT_NE(e.find("node 0"), std::string::npos) << e;
  EXPECT_NE(e.find("over"), std::string::npos) << e;
  c.what_ifs.set("memory", {64.0 * 1048576});
  EXPECT_EQ(run_simulation_isolated(c)["status"], "ok");
}
