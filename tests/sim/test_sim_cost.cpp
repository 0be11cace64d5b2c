// sim: the report's simulation_cost (run/sim_cost.hpp), what a run cost the simulator in its own
// events: counted exactly for two messages, the same in two runs, and larger under the fidelities
// that do more per message.
#include <string>

#include <gtest/gtest.h>

#include "sim_fixtures.hpp"
#include "source_root.hpp"

using namespace zc;
using namespace zc::test;

namespace {

std::uint64_t counted(const nlohmann::json& r, const char* what) {
  EXPECT_EQ(r["status"], "ok") << r.dump().substr(0, 400);
  return r.at("simulation_cost").at(what).get<std::uint64_t>();
}

// Nodes 0 and 1 send 1000 bytes each to node 3 at time 0. Under e-cube routing both need the
// channel from 1 to 3 (0 -> 1 -> 3 and 1 -> 3): the circuit fidelity makes one of them wait.
nlohmann::json two_messages(Fidelity f) {
  return run_custom(sim_config("ipsc2", 4, Topology::Cube, f), [](NodeContext& ctx) {
    Comm& c = ctx.comm();
    if (c.rank() == 0 || c.rank() == 1) c.send(3, 7, Bytes(1000));
    if (c.rank() == 3) {
      c.recv(kAnySource, 7);
      c.recv(kAnySource, 7);
    }
  });
}

RunConfig kurc_point(const std::string& algorithm, Fidelity f) {
  RunConfig c = sim_config("ipsc2", 8, Topology::Cube, f);
  c.algorithm = algorithm;
  c.scene_path = test::kRoot + "/scenes/kurc/2pot.json";
  c.width = c.height = 128;
  return c;
}

} // namespace

// Two messages that contend for a channel: no flow and no network event under analytic; one
// SimGrid transfer and one courier per message under flow; the network's actor, and the events
// of the contended channel's release and hand-over, under circuit.
TEST(SimCost, TwoMessagesCountedExactly) {
  const auto a = two_messages(Fidelity::Analytic), f = two_messages(Fidelity::Flow),
             c = two_messages(Fidelity::Circuit);
  EXPECT_EQ(counted(a, "flows"), 0u);
  EXPECT_EQ(counted(a, "network_events"), 0u);
  EXPECT_EQ(counted(a, "actors"), 4u); // the four ranks
  EXPECT_EQ(counted(f, "flows"), 2u);
  EXPECT_EQ(counted(f, "network_events"), 0u);
  EXPECT_EQ(counted(f, "actors"), 6u); // and a courier for each sender
  EXPECT_EQ(counted(c, "flows"), 0u);
  EXPECT_GE(counted(c, "network_events"), 1u);
  EXPECT_EQ(counted(c, "actors"), 5u); // and the network's actor
  // Each courier sleeps (the start-up) and transfers: two switches a message more than analytic.
  EXPECT_GE(counted(f, "actor_switches"), counted(a, "actor_switches") + 4);
  EXPECT_GT(counted(c, "actor_switches"), counted(a, "actor_switches"));
  for (const auto* r : {&a, &f, &c})
    EXPECT_GE(counted(*r, "time_steps"), 1u);
  EXPECT_GT(counted(f, "time_steps"), counted(a, "time_steps"));
}

// The cost is deterministic (the same numbers in two runs of one configuration) and grows with
// the fidelity: flow solves a SimGrid transfer per message (every message of these two carries
// bytes to another node) where analytic solves none, circuit runs the network's actor and
// processes the events of contended channels (all-to-all merging contends, pairwise does not).
TEST(SimCost, SameInTwoRunsAndGrowsWithFidelity) {
  for (const char* algo : {"pair-rs", "aapc-hbp"}) {
    SCOPED_TRACE(algo);
    nlohmann::json by_fidelity;
    for (Fidelity f : {Fidelity::Analytic, Fidelity::Flow, Fidelity::Circuit}) {
      const auto first = run_simulation_isolated(kurc_point(algo, f));
      const auto second = run_simulation_isolated(kurc_point(algo, f));
      ASSERT_EQ(first["status"], "ok") << first.dump().substr(0, 400);
      EXPECT_EQ(first["simulation_cost"], second["simulation_cost"]) << fidelity_name(f);
      by_fidelity[fidelity_name(f)] = first;
    }
    const auto &a = by_fidelity["analytic"], &f = by_fidelity["flow"], &c = by_fidelity["circuit"];
    const auto messages = a["communication"]["messages"].get<std::uint64_t>();
    ASSERT_GT(messages, 0u);
    EXPECT_EQ(counted(a, "flows"), 0u);
    EXPECT_EQ(counted(f, "flows"), messages);
    EXPECT_EQ(counted(c, "flows"), 0u);
    EXPECT_EQ(counted(a, "network_events"), 0u);
    if (std::string(algo) == "aapc-hbp") {
      EXPECT_GT(counted(c, "network_events"), 0u);
    }
    EXPECT_GT(counted(f, "actor_switches"), counted(a, "actor_switches"));
    EXPECT_GT(counted(c, "actor_switches"), counted(a, "actor_switches"));
    EXPECT_GT(counted(f, "actors"), counted(a, "actors"));
  }
}
