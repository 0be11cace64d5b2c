// sim: a message's virtual time against its closed form for every size, distance, machine and
// fidelity, and contention by fidelity.
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

namespace {

// One simulation per message size, so every measurement is taken while the virtual clock is
// still small (a difference of clock readings near 1 s cannot resolve 1e-12 of 75 us).
nlohmann::json pingpong(const std::string& m, int P, Fidelity f, Topology t = Topology::Cube,
                        WhatIfs o = {}, const std::string& to = "1,3,7,15") {
  nlohmann::json all = {{"status", "ok"}, {"results", nlohmann::json::array()}};
  for (const char* size : {"0B", "1B", "64B", "100B", "101B", "1024B", "65536B"}) {
    RunConfig c = sim_config(m, P, t, f);
    c.algorithm = "pingpong";
    c.what_ifs = o;
    c.options.values = {{"from", "0"}, {"to", to}, {"sizes", size}};
    auto r = run_simulation_isolated(c);
    if (r["status"] != "ok") return r;
    for (auto& x : r["results"])
      all["results"].push_back(x);
  }
  return all;
}

} // namespace

TEST(PointToPoint, DcmCostGrowsByItsPerHopTermVolvoxByWholeSteps) {
  // iPSC/2: circuit switching, so a hop adds only the DCM's per-hop set-up (docs/machines.md), the
  // same for short and long messages.
  auto dcm = one_way(sim_config("ipsc2", 32, Topology::Cube, Fidelity::Circuit), "1,3,7,15,31",
                     "64B,4096B");
  const double per_hop = machine_spec("ipsc2").net.per_hop_s;
  ASSERT_GT(per_hop, 0);
  for (double m : {64.0, 4096.0})
    for (int h = 2; h <= 5; ++h)
      expect_rel(dcm.at({m, h}), dcm.at({m, 1}) + (h - 1) * per_hop, 1e-12,
                 "ipsc2, " + std::to_string(h) + " hops");
  // Volvox: every hop is a whole store-and-forward step.
  auto t800 = one_way(sim_config("volvox", 32, Topology::Cube, Fidelity::Circuit), "1,3,7,15,31",
                      "64B,4096B");
  for (double m : {64.0, 4096.0})
    for (int h = 2; h <= 5; ++h)
      expect_rel(t800.at({m, h}), h * t800.at({m, 1}), 1e-12, "volvox");
}

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
  WhatIfs o;
  o.set("latency", {0});
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

TEST(PointToPoint, SharedRingChannelSlowsCircuitBothWaysAndAcrossTheWrap) {
  // 8-node ring: 7 -> 1 goes 7-0-1 and 0 -> 1 needs (0,1); 1 -> 7 goes 1-0-7 and 0 -> 7 needs
  // (0,7), the backward channel across the wrap. Each pair shares one channel; the other pairs
  // share none (a link's two directions are two channels).
  const double m = 65536;
  auto run = [&](int a, int b, int c2, int d) {
    auto r = run_custom(sim_config("ipsc2", 8, Topology::Ring, Fidelity::Circuit),
                        [=](NodeContext& ctx) {
                          Comm& c = ctx.comm();
                          if (c.rank() == a) c.send(b, 0, Bytes(std::size_t(m)));
                          if (c.rank() == c2) c.send(d, 1, Bytes(std::size_t(m)));
                          if (c.rank() == b) c.recv(a, 0);
                          if (c.rank() == d) c.recv(c2, 1);
                        });
    EXPECT_EQ(r["status"], "ok") << r.dump();
    return r["virtual_time_s"].get<double>();
  };
  const double two_hops = machine_spec("ipsc2").net.message_time(m, 2);
  const double three_hops = machine_spec("ipsc2").net.message_time(m, 3);
  EXPECT_GT(run(7, 1, 0, 1), two_hops * 1.5);
  EXPECT_GT(run(1, 7, 0, 7), two_hops * 1.5);
  expect_rel(run(6, 1, 2, 5), three_hops, 1e-12, "no channel shared");
  const double one_hop = machine_spec("ipsc2").net.message_time(m, 1);
  expect_rel(run(0, 1, 1, 0), one_hop, 1e-12, "a link both ways");
  expect_rel(run(7, 0, 0, 7), one_hop, 1e-12, "the wrap both ways");
}

TEST(PointToPoint, RanksDueAtOneVirtualTimeRunInRankOrder) {
  // 4-node cube, circuit: 0 -> 3 (channels 0-1, 1-3) and 1 -> 3 (channel 1-3) are sent at the same
  // virtual time, after computing. Rank 1's wake-up is set first (at time 0, rank 0's at the end
  // of its first part), yet rank 0 runs first at that time: its message has channel (1,3) first
  // and reaches node 3 first, although it has the longer way.
  auto r =
      run_custom(sim_config("ipsc2", 4, Topology::Cube, Fidelity::Circuit), [](NodeContext& ctx) {
        Comm& c = ctx.comm();
        Counters w;
        w.pixels_cleared = 1000;
        if (c.rank() == 0) {
          ctx.charge(w);
          ctx.charge(w);
          c.send(3, 0, Bytes(1024));
        }
        if (c.rank() == 1) {
          w.pixels_cleared *= 2; // the same date: doubling is exact
          ctx.charge(w);
          c.send(3, 0, Bytes(1024));
        }
        if (c.rank() == 3) {
          int first = -1;
          c.recv(kAnySource, 0, &first);
          c.recv(kAnySource, 0);
          ctx.metrics()["first"] = first;
        }
      });
  ASSERT_EQ(r["status"], "ok") << r.dump();
  EXPECT_EQ(r["per_node"][3]["metrics"]["first"], 0);
}

// Under the flow fidelity every message is an actor on a small stack (16 KiB; 64 when a run sets a
// log level: SimGrid's logging formats on the actor's stack). With guard pages on, an overflow
// would kill the run instead of writing past the stack unseen.
TEST(PointToPoint, FlowMessageActorsFitTheirStacksWithGuardPages) {
  const auto all_to_all = [](NodeContext& ctx) {
    Comm& c = ctx.comm();
    std::vector<SendHandle> sends;
    for (int k = 1; k < c.size(); ++k)
      sends.push_back(c.isend((c.rank() + k) % c.size(), 0, Bytes(std::size_t(1000 * k))));
    for (int k = 1; k < c.size(); ++k)
      c.recv((c.rank() + c.size() - k) % c.size(), 0);
    for (auto& s : sends)
      s->wait();
  };
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--cfg=contexts/guard-size:1"},
        std::vector<std::string>{"--cfg=contexts/guard-size:1", "--log=root.thres:debug",
                                 "--log=root.app:file:/dev/null"}}) {
    RunConfig cfg = sim_config("ipsc2", 8, Topology::Cube, Fidelity::Flow);
    cfg.simgrid_args = extra;
    const auto r = run_custom(cfg, all_to_all);
    EXPECT_EQ(r["status"], "ok") << extra.back() << ": " << r.dump();
    EXPECT_GT(r.value("virtual_time_s", 0.0), 0.0) << extra.back();
  }
}

// The sender's own measurements are the run's results: no message carries them to node 0, so the
// run holds exactly a ping and a pong per target and size, and node 0 keeps no results.
TEST(PointToPoint, ResultsAreTheSendersWithoutAnExtraMessage) {
  RunConfig c = sim_config("ipsc860", 8, Topology::Cube, Fidelity::Circuit);
  c.algorithm = "pingpong";
  c.options.values = {{"from", "3"}, {"to", "0,5"}, {"sizes", "64B,4096B"}};
  const auto r = run_simulation_isolated(c);
  ASSERT_EQ(r["status"], "ok") << r.dump();
  ASSERT_EQ(r["results"].size(), 4u) << r.dump();
  for (const auto& x : r["results"])
    EXPECT_EQ(x["from"], 3);
  EXPECT_EQ(r["communication"]["messages"], 2 * 4);
  EXPECT_TRUE(r["per_node"][3]["metrics"].contains("results"));
  EXPECT_FALSE(r["per_node"][0].contains("metrics")) << r["per_node"][0].dump();
}
