// sim: runs that must fail rather than report success.

#include <gtest/gtest.h>

#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

TEST(Robustness, DeadlockIsAFailureNotSuccess) {
  // Node 0 waits for a message node 1 never sends: SimGrid ends the run, which must say so.
  auto r =
      run_custom(sim_config("ipsc2", 2, Topology::Cube, Fidelity::Circuit), [](NodeContext& ctx) {
        if (ctx.rank() == 0) ctx.comm().recv(1, 7);
      });
  EXPECT_EQ(r.value("status", ""), "error");
  EXPECT_NE(r.value("error", "").find("deadlock"), std::string::npos) << r.dump();
  EXPECT_NE(r.value("error", "").find("node 0"), std::string::npos) << r.dump();
}
