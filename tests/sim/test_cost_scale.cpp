// sim: virtual time scales exactly with a global cost factor.
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "machine/machine.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

TEST(Scaling, VirtualTimeScalesExactlyWithAGlobalCostFactor) {
  RunConfig base = sim_config("ipsc860", 8, Topology::Cube, Fidelity::Circuit);
  base.algorithm = "sequential";
  base.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";
  base.width = base.height = 128;
  const auto check = find_algorithm("comm-check").node;
  auto work = [check](NodeContext& ctx) {
    check(ctx);
    Counters c;
    c.pixels_generated = 1000 + 10 * std::uint64_t(ctx.rank());
    ctx.charge(c);
    check(ctx);
  };
  for (Fidelity f : {Fidelity::Analytic, Fidelity::Flow, Fidelity::Circuit}) {
    base.fidelity = f;
    const double t1 = run_custom(base, work)["virtual_time_s"].get<double>();
    const double s1 = run_simulation_isolated(base)["virtual_time_s"].get<double>();
    for (double k : {1e-9, 1e-3, 7.0, 1e6}) {
      RunConfig c = base;
      c.what_ifs.set("cost-scale", {k});
      expect_rel(run_custom(c, work)["virtual_time_s"].get<double>(), k * t1, 1e-12,
                 std::string("collectives, k=") + std::to_string(k) + " " + fidelity_name(f));
      expect_rel(run_simulation_isolated(c)["virtual_time_s"].get<double>(), k * s1, 1e-12,
                 std::string("sequential, k=") + std::to_string(k));
    }
  }
}
