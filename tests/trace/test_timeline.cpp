// The report's timeline: phases with begin and end, activities that add up to the
// report's busy and communication times, every message with its send, arrival and receive times.
#include <gtest/gtest.h>

#include "machine/machine.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

RunConfig traced(const std::string& algo, const std::string& scene, int P, Fidelity f) {
  RunConfig c = sim_config("ipsc2", P, Topology::Cube, f);
  c.algorithm = algo;
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/" + scene;
  c.width = c.height = 128;
  c.timeline = true;
  return c;
}

// Closed form of one message under analytic fidelity (no contention): the host link, when the
// host computer is an end, plus the machine's network to or from node 0.
double closed_form(const NetworkParams& net, const nlohmann::json& m, int P) {
  const double bytes = m["bytes"].get<double>();
  const int hops = m["hops"].get<int>();
  const bool host = m["src"] == P || m["dst"] == P;
  return host ? net.host_link_time(bytes) + net.message_time(bytes, hops - 1)
              : net.message_time(bytes, hops);
}

} // namespace

TEST(Timeline, OnlyWhenAskedAndWithoutChangingTheRun) {
  RunConfig c = traced("aapc-hbp", "scenes/kurc/2pot.json", 4, Fidelity::Circuit);
  const auto with = run_simulation_isolated(c);
  c.timeline = false;
  const auto without = run_simulation_isolated(c);
  ASSERT_EQ(with["status"], "ok") << with.dump();
  ASSERT_EQ(without["status"], "ok") << without.dump();
  EXPECT_TRUE(with.contains("timeline"));
  EXPECT_FALSE(without.contains("timeline"));
  EXPECT_EQ(with["virtual_time_s"], without["virtual_time_s"]);
  EXPECT_EQ(with["per_node"], without["per_node"]);
}

TEST(Timeline, ActivitiesAddUpToBusyAndCommunication) {
  for (const char* algo : {"aapc-hbp", "pair-rs", "elastic", "node-initiated"}) {
    const std::string scene = std::string(algo) == "node-initiated"
                                  ? "scenes/blazek/spheres_16.json"
                                  : "scenes/kurc/2pot.json";
    const auto r = run_simulation_isolated(traced(algo, scene, 8, Fidelity::Circuit));
    ASSERT_EQ(r["status"], "ok") << algo << r.dump();
    const auto& nodes = r["timeline"]["nodes"];
    ASSERT_EQ(nodes.size(), r["per_node"].size()) << algo;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      double busy = 0, comm = 0;
      for (const auto& a : nodes[i]["activities"])
        (a[0] == "compute" ? busy : comm) += a[2].get<double>() - a[1].get<double>();
      const auto& pn = r["per_node"][i];
      EXPECT_NEAR(busy, pn["busy_s"].get<double>(), 1e-9) << algo << " node " << i;
      EXPECT_NEAR(comm, pn["comm_s"].get<double>(), 1e-9) << algo << " node " << i;
      // Phase spans sum to the report's phase totals.
      std::map<std::string, double> sum;
      for (const auto& p : nodes[i]["phases"])
        sum[p["name"]] += p["end_s"].get<double>() - p["begin_s"].get<double>();
      for (const auto& [name, t] : pn["phases"].items())
        EXPECT_NEAR(sum[name], t.get<double>(), 1e-9) << algo << " node " << i << " " << name;
    }
    EXPECT_EQ(r["timeline"]["messages"].size(), r["communication"]["messages"].get<std::size_t>());
  }
}

TEST(Timeline, EveryMessageTakesItsClosedFormUnderAnalyticFidelity) {
  const NetworkParams& net = machine_spec("ipsc2").net;
  for (const char* algo : {"aapc-hbp", "zbuf-exc", "host-initiated"}) {
    const std::string scene = std::string(algo) == "host-initiated"
                                  ? "scenes/blazek/spheres_16.json"
                                  : "scenes/kurc/2pot.json";
    const int P = 16;
    const auto r = run_simulation_isolated(traced(algo, scene, P, Fidelity::Analytic));
    ASSERT_EQ(r["status"], "ok") << algo << r.dump();
    const auto& msgs = r["timeline"]["messages"];
    ASSERT_GT(msgs.size(), 0u) << algo;
    for (const auto& m : msgs) {
      ASSERT_FALSE(m["arrival_s"].is_null()) << algo << " never received: " << m.dump();
      const double took = m["arrival_s"].get<double>() - m["send_start_s"].get<double>();
      EXPECT_NEAR(took, closed_form(net, m, P), 1e-12 + 1e-9 * took) << algo << " " << m.dump();
      EXPECT_LE(m["arrival_s"].get<double>(), m["recv_done_s"].get<double>()) << m.dump();
    }
  }
}
