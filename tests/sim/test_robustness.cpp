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

TEST(Robustness, DeadlockAfterMessagesUnderEveryFidelity) {
  // Messages first (under the flow fidelity their couriers are left idle), then node 0 waits for
  // one more that never comes: the run still ends, as a deadlock, whatever carried the messages.
  for (Fidelity f : {Fidelity::Analytic, Fidelity::Flow, Fidelity::Circuit}) {
    SCOPED_TRACE(fidelity_name(f));
    auto r = run_custom(sim_config("ipsc2", 4, Topology::Cube, f), [](NodeContext& ctx) {
      Comm& c = ctx.comm();
      for (int k = 0; k < 3; ++k) {
        if (c.rank() != 0) c.send(0, k, Bytes(100 * std::size_t(c.rank())));
        if (c.rank() == 0)
          for (int s = 1; s < 4; ++s)
            c.recv(s, k);
      }
      if (c.rank() == 0) c.recv(1, 7);
    });
    EXPECT_EQ(r.value("status", ""), "error");
    EXPECT_NE(r.value("error", "").find("deadlock"), std::string::npos) << r.dump();
    EXPECT_NE(r.value("error", "").find("node 0"), std::string::npos) << r.dump();
  }
}
