// Communication layer on the simulated machines: message times against their closed forms,
// contention by fidelity, collectives' data and times, cost scaling.
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "machine/machine.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

// One simulation per message size, so every measurement is taken while the virtual clock is
// still small (a difference of clock readings near 1 s cannot resolve 1e-12 of 75 us).
nlohmann::json pingpong(const std::string& m, int P, Fidelity f, Topology t = Topology::Cube,
                        Overrides o = {}, const std::string& to = "1,3,7,15") {
  nlohmann::json all = {{"status", "ok"}, {"results", nlohmann::json::array()}};
  for (const char* size : {"0B", "1B", "64B", "100B", "101B", "1024B", "65536B"}) {
    SimConfig c = sim_config(m, P, t, f);
    c.algorithm = "pingpong";
    c.overrides = o;
    c.options.values = {{"from", "0"}, {"to", to}, {"sizes", size}};
    auto r = run_simulation_isolated(c);
    if (r["status"] != "ok") return r;
    for (auto& x : r["results"])
      all["results"].push_back(x);
  }
  return all;
}

} // namespace

TEST(PointToPoint, EqualsTheFormulaForEverySizeDistanceMachineAndFidelity) {
  for (const std::string m : {"ipsc2", "ipsc860", "volvox"})
    for (Fidelity f : {Fidelity::Analytic, Fidelity::Flow, Fidelity::Circuit}) {
      auto r = pingpong(m, 16, f);
      ASSERT_EQ(r["status"], "ok") << r.dump();
      const NetworkParams& net = machine_spec(m).net;
      ASSERT_EQ(r["results"].size(), 4u * 7u); // 1, 2, 3 and 4 hops
      for (const auto& x : r["results"])
        expect_rel(x["one_way_s"].get<double>(),
                   net.message_time(x["bytes"].get<double>(), x["hops"].get<int>()), 1e-12,
                   m + " " + fidelity_name(f) + " " + x.dump());
    }
}

TEST(PointToPoint, RingDistancesAndZeroLatency) {
  auto r = pingpong("volvox", 8, Fidelity::Circuit, Topology::Ring, {}, "1,2,3,4,5");
  ASSERT_EQ(r["status"], "ok") << r.dump();
  ASSERT_FALSE(r["results"].empty()) << r.dump();
  const NetworkParams& net = machine_spec("volvox").net;
  for (const auto& x : r["results"])
    expect_rel(x["one_way_s"].get<double>(),
               net.message_time(x["bytes"].get<double>(), x["hops"].get<int>()), 1e-12, x.dump());
  Overrides o;
  o.latency_s = 0;
  auto z = pingpong("ipsc2", 4, Fidelity::Flow, Topology::Cube, o, "1,3");
  ASSERT_EQ(z["status"], "ok") << z.dump();
  ASSERT_FALSE(z["results"].empty()) << z.dump();
  // No start-up left: the bytes at the channel rate and the DCM's per-hop set-up.
  const double per_hop = machine_spec("ipsc2").net.per_hop_s;
  for (const auto& x : z["results"])
    expect_rel(x["one_way_s"].get<double>(),
               x["bytes"].get<double>() / 2.8e6 + (x["hops"].get<int>() - 1) * per_hop, 1e-12,
               x.dump());
}

TEST(PointToPoint, SharedChannelSlowsFlowAndCircuitNotAnalytic) {
  // 4-node cube: 0 -> 3 goes 0-1-3, 1 -> 3 goes 1-3: both need channel (1,3).
  const double m = 65536;
  auto run = [&](Fidelity f, bool both) {
    return run_custom(sim_config("ipsc2", 4, Topology::Cube, f),
                      [=](NodeContext& ctx) {
                        Comm& c = ctx.comm();
                        if (c.rank() == 0) c.send(3, 0, Bytes(std::size_t(m)));
                        if (c.rank() == 1 && both) c.send(3, 0, Bytes(std::size_t(m)));
                        if (c.rank() == 3) {
                          c.recv(0, 0);
                          if (both) c.recv(1, 0);
                        }
                      })["virtual_time_s"]
        .get<double>();
  };
  const double alone = machine_spec("ipsc2").net.message_time(m, 2);
  for (Fidelity f : {Fidelity::Analytic, Fidelity::Flow, Fidelity::Circuit}) {
    expect_rel(run(f, false), alone, 1e-12, fidelity_name(f));
    if (f == Fidelity::Analytic)
      expect_rel(run(f, true), alone, 1e-12, "analytic, shared");
    else
      EXPECT_GT(run(f, true), alone * 1.5) << fidelity_name(f);
  }
}

namespace {

// The comm-check algorithm (algo/comm_check: the same self-test runs under MPI, tests/mpi) on a
// simulated machine.
void expect_all_good(SimConfig c, int P) {
  c.algorithm = "comm-check";
  const auto rep = run_simulation_isolated(c);
  ASSERT_EQ(rep["status"], "ok") << rep.dump();
  ASSERT_EQ(int(rep["per_node"].size()), P);
  for (const auto& n : rep["per_node"])
    EXPECT_TRUE(n["metrics"]["comm_check_failures"].empty()) << n.dump();
}

} // namespace

TEST(Collectives, DeliverTheRightDataOnCubes) {
  for (int P : {1, 2, 4, 8, 16, 32})
    expect_all_good(sim_config("ipsc860", P, Topology::Cube, Fidelity::Circuit), P);
}

TEST(Collectives, DeliverTheRightDataOnRings) {
  for (int P : {2, 3, 4, 5, 8, 16})
    expect_all_good(sim_config("volvox", P, Topology::Ring, Fidelity::Flow), P);
}

TEST(Collectives, ClosedFormTimesUnderAnalytic) {
  const NetworkParams& n = machine_spec("ipsc2").net;
  for (int P : {2, 8, 32}) {
    const int d = log2_exact(P);
    const std::size_t m = 4000;
    auto bc = run_custom(
        sim_config("ipsc2", P, Topology::Cube, Fidelity::Analytic),
        [&](NodeContext& ctx) { coll::broadcast(ctx.comm(), 0, Bytes(ctx.rank() == 0 ? m : 0)); });
    expect_rel(bc["virtual_time_s"].get<double>(), d * n.message_time(double(m), 1), 1e-12,
               "broadcast P=" + std::to_string(P));
    // Multi-reduce by recursive doubling: d exchanges of the whole vector.
    auto ar = run_custom(
        sim_config("ipsc2", P, Topology::Cube, Fidelity::Analytic), [&](NodeContext& ctx) {
          coll::allreduce(ctx.comm(), std::vector<std::int64_t>(512, 1), coll::Op::Sum);
        });
    expect_rel(ar["virtual_time_s"].get<double>(), d * n.message_time(512 * 8, 1), 1e-12,
               "allreduce P=" + std::to_string(P));
    // Multi-broadcast: step i carries 2^i blocks (4-byte count, 12-byte header per block).
    const std::size_t b = 1000;
    auto ag = run_custom(sim_config("ipsc2", P, Topology::Cube, Fidelity::Analytic),
                         [&](NodeContext& ctx) { coll::allgatherv(ctx.comm(), Bytes(b)); });
    double want = 0;
    for (int i = 0; i < d; ++i)
      want += n.message_time(4.0 + (1 << i) * (12.0 + b), 1);
    expect_rel(ag["virtual_time_s"].get<double>(), want, 1e-12, "allgather P=" + std::to_string(P));
  }
}

TEST(Scaling, VirtualTimeScalesExactlyWithAGlobalCostFactor) {
  SimConfig base = sim_config("ipsc860", 8, Topology::Cube, Fidelity::Circuit);
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
      SimConfig c = base;
      c.overrides.cost_scale = k;
      expect_rel(run_custom(c, work)["virtual_time_s"].get<double>(), k * t1, 1e-12,
                 std::string("collectives, k=") + std::to_string(k) + " " + fidelity_name(f));
      expect_rel(run_simulation_isolated(c)["virtual_time_s"].get<double>(), k * s1, 1e-12,
                 std::string("sequential, k=") + std::to_string(k));
    }
  }
}

TEST(Sequential, VirtualTimeIsCountsTimesCosts) {
  for (const std::string m : {"ipsc2", "ipsc860"}) {
    SimConfig c = sim_config(m, 1, Topology::Cube, Fidelity::Circuit);
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

TEST(Memory, ExceedingNodeMemoryFailsAndSaysWhereAndByHowMuch) {
  SimConfig c = sim_config("ipsc2", 1, Topology::Cube, Fidelity::Circuit);
  c.algorithm = "sequential";
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";
  c.width = c.height = 1024; // 7 bytes a pixel (depth and colour): 7.3 MB > 4 MB
  auto r = run_simulation_isolated(c);
  EXPECT_EQ(r["status"], "out_of_memory");
  const std::string e = r["error"];
  EXPECT_NE(e.find("node 0"), std::string::npos) << e;
  EXPECT_NE(e.find("over"), std::string::npos) << e;
  c.overrides.memory_bytes = 64.0 * 1048576;
  EXPECT_EQ(run_simulation_isolated(c)["status"], "ok");
}
