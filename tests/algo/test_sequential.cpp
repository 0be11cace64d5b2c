// algo/sequential: the reference's virtual time is its counts times their costs.
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "machine/machine.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

TEST(Sequential, VirtualTimeIsCountsTimesCosts) {
  for (const std::string m : {"ipsc2", "ipsc860"}) {
    RunConfig c = sim_config(m, 1, Topology::Cube, Fidelity::Circuit);
    c.algorithm = "sequential";
    c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";
    c.compare_with_sequential = true;
    auto r = run_simulation_isolated(c);
    ASSERT_EQ(r["status"], "ok") << r.dump();
    Counters k;
#define ZC_FROM_JSON(f) k.f = r["counters"][#f].get<std::uint64_t>();
    ZC_COUNTER_FIELDS(ZC_FROM_JSON)
#undef ZC_FROM_JSON
    EXPECT_EQ(k.triangles_in, 3751u);
    expect_rel(r["virtual_time_s"].get<double>(), machine_spec(m).cost.seconds(k), 1e-12, m);
    EXPECT_EQ(r["image"]["identical_to_sequential"], true);
  }
}
