// Communication layer, second part: message ordering, any-source and the host as a rank, the
// remaining collectives' closed forms under the analytic fidelity, rings of every size, what-if
// overrides, user-edited platform files, and the simulator's own speed (wall time per simulated
// message and per collective on 32 nodes, printed by this test).
#include <bit>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include <unistd.h>

#include <gtest/gtest.h>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "machine/topology.hpp"
#include "machine/units.hpp"
#include "sim_fixtures.hpp"
#include "util/error.hpp"

#include <simgrid/s4u.hpp>

using namespace zc;
using namespace zc::test;

namespace {

// One-way times of a ping-pong from node 0, indexed by (bytes, hops).
std::map<std::pair<double, int>, double> one_way(const SimConfig& base, const std::string& to,
                                                 const std::string& sizes) {
  SimConfig c = base;
  c.algorithm = "pingpong";
  c.options.values = {{"from", "0"}, {"to", to}, {"sizes", sizes}};
  auto r = run_simulation_isolated(c);
  EXPECT_EQ(r["status"], "ok") << r.dump();
  std::map<std::pair<double, int>, double> t;
  for (const auto& x : r["results"])
    t[{x["bytes"].get<double>(), x["hops"].get<int>()}] = x["one_way_s"].get<double>();
  return t;
}

} // namespace

TEST(Units, SpeedsTheWaySimGridWritesThem) {
  EXPECT_DOUBLE_EQ(parse_speed("10Mf"), 10e6);
  EXPECT_DOUBLE_EQ(parse_speed("1Gf"), 1e9);
  EXPECT_DOUBLE_EQ(parse_speed("2.5kf"), 2500);
  EXPECT_THROW(parse_speed("10MHz", "--speed"), UsageError);
  EXPECT_DOUBLE_EQ(parse_time("0us"), 0);
  EXPECT_DOUBLE_EQ(parse_bytes("8MiB"), 8.0 * 1048576);
}

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

TEST(Overrides, WhatIfFlagsChangeTheFormula) {
  SimConfig c = sim_config("ipsc860", 8, Topology::Cube, Fidelity::Analytic);
  c.overrides.latency_s = 1e-3;
  c.overrides.bandwidth_Bps = 1e6;
  c.overrides.per_hop_s = 50e-6;
  auto t = one_way(c, "1,7", "10B,1000B");
  expect_rel(t.at({10.0, 1}), 1e-3 + 10e-6, 1e-12, "short");
  expect_rel(t.at({1000.0, 3}), 1e-3 + 1000e-6 + 2 * 50e-6, 1e-12, "long, 3 hops");
  // The flow model reads the bandwidth from its links: the override must reach them too.
  c.fidelity = Fidelity::Flow;
  auto f = one_way(c, "7", "1000B");
  expect_rel(f.at({1000.0, 3}), 1e-3 + 1000e-6 + 2 * 50e-6, 1e-12, "flow");
  // --cpu-scale multiplies the CPU and nothing else.
  SimConfig s = sim_config("ipsc2", 1, Topology::Cube, Fidelity::Circuit);
  s.algorithm = "sequential";
  s.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";
  s.width = s.height = 96;
  const double t1 = vtime(run_simulation_isolated(s));
  s.overrides.cpu_scale = 0.25;
  expect_rel(vtime(run_simulation_isolated(s)), 0.25 * t1, 1e-12, "cpu-scale");
}

// A report says which model made its times: the what-ifs in force, every CPU cost (scaled), the
// host link, and every option of the algorithm with its default.
TEST(Overrides, TheReportStatesTheWhatIfsCpuCostsAndOptions) {
  SimConfig s = sim_config("ipsc860", 2, Topology::Cube, Fidelity::Circuit);
  s.algorithm = "elastic";
  s.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";
  s.width = s.height = 32;
  const auto plain = run_simulation_isolated(s);
  ASSERT_EQ(plain.value("status", ""), "ok") << plain.dump();
  EXPECT_TRUE(plain["what_if"].is_object() && plain["what_if"].empty());
  EXPECT_EQ(plain["options"]["vertices"], "broadcast");
  EXPECT_EQ(plain["options"]["timed"], "picture");
  EXPECT_DOUBLE_EQ(plain["model"]["host_startup_s"].get<double>(), 1e-3);
  const double vt = plain["model"]["cpu_seconds"]["vertices_transformed"].get<double>();
  EXPECT_GT(vt, 0);
  s.overrides.cpu_scale = 0.5;
  s.overrides.latency_s = 20e-6;
  const auto w = run_simulation_isolated(s);
  ASSERT_EQ(w.value("status", ""), "ok") << w.dump();
  EXPECT_DOUBLE_EQ(w["what_if"]["cpu_scale"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(w["what_if"]["latency_s"].get<double>(), 20e-6);
  EXPECT_FALSE(w["what_if"].contains("bandwidth_Bps"));
  expect_rel(w["model"]["cpu_seconds"]["vertices_transformed"].get<double>(), 0.5 * vt, 1e-12,
             "cpu-scale in the report");
}

namespace {

// The platform text of a built-in machine with `from` replaced by `to`, written to a file.
std::string edited_platform(const std::string& machine, int P, Topology topo,
                            const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string x = platform_xml(machine_spec(machine), P, topo);
  for (const auto& [from, to] : edits) {
    const auto at = x.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) x.replace(at, from.size(), to);
  }
  static int serial = 0;
  const auto path =
      std::filesystem::temp_directory_path() /
      ("zcube-test-edited-" + std::to_string(::getpid()) + "-" + std::to_string(serial++) + ".xml");
  std::ofstream(path) << x;
  return path.string();
}

} // namespace

TEST(Platforms, SimGridFiguresOfAUserEditedFileAreTheMachine) {
  const NetworkParams& n = machine_spec("ipsc860").net;
  // Channel bandwidth / 10, channel latency (the per-hop cost) 10 us -> 30 us, the short
  // protocol's start-up (SMPI's receive overhead) + 1 ms: each changes the time as in SimGrid.
  const std::string path =
      edited_platform("ipsc860", 4, Topology::Cube,
                      {{"bw=\"2777777.777777778Bps\"", "bw=\"277777.7777777778Bps\""},
                       {"lat=\"10000ns\"", "lat=\"30us\""},
                       {"value=\"0:5.9239999999999995e-05:0;", "value=\"0:0.00105924:0;"}});
  SimConfig c = sim_config(path, 0, Topology::Cube, Fidelity::Circuit); // P from the file
  auto t = one_way(c, "3", "10B,1000B");
  std::filesystem::remove(path);
  const double per_byte = 10 * n.per_byte_s, hop = 30e-6, envelope = 16 * (per_byte - n.per_byte_s);
  // start-up = smpi/or + lat + 16 bytes / bw: the edited latency and rate enter it as in SMPI.
  expect_rel(t.at({10.0, 2}), 1e-3 + n.startup_short_s + envelope + 20e-6 + 10 * per_byte + hop,
             1e-9, "edited short");
  expect_rel(t.at({1000.0, 2}), n.startup_long_s + envelope + 20e-6 + 1000 * per_byte + hop, 1e-9,
             "edited long");
}

TEST(Platforms, HostSpeedIsTheClockThatScalesCompute) {
  SimConfig s = sim_config("ipsc2", 1, Topology::Cube, Fidelity::Circuit);
  s.algorithm = "sequential";
  s.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";
  s.width = s.height = 64;
  const double t16 = vtime(run_simulation_isolated(s));
  s.machine =
      edited_platform("ipsc2", 1, Topology::Cube, {{"speed=\"16Mf\" bw", "speed=\"160Mf\" bw"}});
  s.nodes = 0;
  const double t160 = vtime(run_simulation_isolated(s));
  std::filesystem::remove(s.machine);
  expect_rel(t160, t16 / 10, 1e-12, "10x the clock, a tenth of the time");
}

TEST(Platforms, SimGridRoutesAreTheTopologyRoutes) {
  // Every route SimGrid computes from the file (a torus: dimension order) is the route zcube's
  // circuit fidelity holds (topology.cpp): e-cube on the cube, the shorter way on the ring
  // (clockwise on a tie, but for one pair).
  for (auto [P, topo] :
       {std::pair{32, Topology::Cube}, std::pair{1024, Topology::Cube},
        std::pair{7, Topology::Ring}, std::pair{8, Topology::Ring}, std::pair{2, Topology::Ring}}) {
    SimConfig c = sim_config("ipsc2", P, topo, Fidelity::Analytic);
    auto r = run_custom(c, [P, topo](NodeContext& ctx) {
      const int me = ctx.comm().rank();
      if (P > 64 && me % 97 != 0) return; // a sample of sources on the big cube
      auto* self = simgrid::s4u::Host::current();
      auto* e = simgrid::s4u::Engine::get_instance();
      for (int d = 0; d < P; ++d) {
        std::vector<simgrid::s4u::Link*> links;
        self->route_to(e->host_by_name(node_host_name(d)), links, nullptr);
        // One known difference: on an even ring SimGrid goes from P/2 to 0 counter-clockwise,
        // zcube (and the papers' figures) clockwise; the hop count is the same.
        if (topo == Topology::Ring && P % 2 == 0 && me == P / 2 && d == 0) continue;
        const auto want = route(topo, P, me, d);
        if (links.size() != want.size())
          throw std::runtime_error("route " + std::to_string(me) + "->" + std::to_string(d) + ": " +
                                   std::to_string(links.size()) + " links");
        for (std::size_t i = 0; i < want.size(); ++i) {
          // Torus link of the lower node of the pair in that dimension (UP: away from it).
          auto [a, b] = want[i];
          const std::string name = links[i]->get_name();
          const bool ok =
              name.find("_from_" + std::to_string(a) + "_to_" + std::to_string(b) + "_UP") !=
                  name.npos ||
              name.find("_from_" + std::to_string(b) + "_to_" + std::to_string(a) + "_DOWN") !=
                  name.npos;
          if (!ok)
            throw std::runtime_error("route " + std::to_string(me) + "->" + std::to_string(d) +
                                     " hop " + std::to_string(i) + ": " + name);
        }
      }
    });
    EXPECT_EQ(r["status"], "ok") << P << " " << topology_name(topo) << ": " << r.value("error", "");
  }
}

TEST(Comm, FifoPerSourceAndTagAnySourceAndTheHostAsARank) {
  SimConfig c = sim_config("ipsc2", 8, Topology::Cube, Fidelity::Flow);
  auto a = std::make_shared<Algorithm>();
  a->name = "test";
  a->uses_host = true;
  a->node = [](NodeContext& ctx) {
    Comm& m = ctx.comm();
    const int r = m.rank(), P = m.size();
    int bad = 0;
    if (r == 0) {
      // Large first: later, smaller messages would finish earlier if nothing kept the order.
      std::vector<SendHandle> hs;
      for (int i = 0; i < 20; ++i) {
        Bytes b(std::size_t(4000 - 190 * i), std::uint8_t(i));
        hs.push_back(m.isend(1, 5, std::move(b)));
        hs.push_back(m.isend(1, 6, Bytes(1, std::uint8_t(100 + i))));
      }
      for (auto& h : hs)
        h->wait();
    }
    if (r == 1) {
      for (int i = 0; i < 20; ++i) // tag 6 first: tags are independent streams
        bad += m.recv(0, 6).at(0) != 100 + i;
      for (int i = 0; i < 20; ++i) {
        Bytes b = m.recv(kAnySource, 5);
        bad += b.size() != std::size_t(4000 - 190 * i) || b.at(0) != i;
      }
    }
    // Any source: every other node reports to node 0.
    if (r != 0) m.send(0, 7, pack(std::vector<std::int32_t>{r}));
    if (r == 0) {
      std::vector<int> seen(P, 0);
      for (int k = 1; k < P; ++k) {
        int from = -1;
        const auto v = unpack<std::int32_t>(m.recv(kAnySource, 7, &from));
        bad += v.at(0) != from;
        seen.at(from)++;
      }
      for (int k = 1; k < P; ++k)
        bad += seen[k] != 1;
    }
    // The host computer (srm) is rank P: it greets node P-1, which answers.
    if (r == P - 1) {
      Bytes b = m.recv(m.host_rank(), 9);
      bad += b.size() != 333;
      m.send(m.host_rank(), 9, std::move(b));
    }
    bad += m.is_host();
    ctx.metrics()["bad"] = bad;
  };
  a->host = [](NodeContext& ctx) {
    Comm& m = ctx.comm();
    int bad = !m.is_host() || m.rank() != m.size();
    m.send(m.size() - 1, 9, Bytes(333, 1));
    bad += m.recv(m.size() - 1, 9).size() != 333;
    ctx.metrics()["bad"] = bad;
  };
  c.custom = a;
  auto r = run_simulation_isolated(c);
  ASSERT_EQ(r["status"], "ok") << r.dump();
  ASSERT_EQ(r["per_node"].size(), 9u); // 8 nodes + srm
  for (const auto& n : r["per_node"])
    EXPECT_EQ(n["metrics"]["bad"], 0) << n.dump();

  // Host link, then the e-cube path from node 0, under analytic: closed form.
  SimConfig h = sim_config("ipsc860", 8, Topology::Cube, Fidelity::Analytic);
  auto ha = std::make_shared<Algorithm>();
  ha->name = "test";
  ha->uses_host = true;
  ha->node = [](NodeContext& ctx) {
    if (ctx.rank() == 7) ctx.comm().recv(ctx.comm().host_rank(), 1);
  };
  ha->host = [](NodeContext& ctx) { ctx.comm().send(7, 1, Bytes(5000)); };
  h.custom = ha;
  const NetworkParams& n = machine_spec("ipsc860").net;
  expect_rel(vtime(run_simulation_isolated(h)), n.host_link_time(5000) + n.message_time(5000, 3),
             1e-12, "host to node 7");
}

// --host-latency and --host-bandwidth (docs/machines.md, the host link): a host-to-node-0 message
// of n bytes takes host start-up + n / host bandwidth under the analytic fidelity, before and after
// the what-if, and node 0's answer back as long; the report names them; the node channels keep
// their figures.
TEST(Overrides, HostLinkWhatIfsGiveTheHostMessagesClosedForm) {
  const double n = 4096;
  auto ha = std::make_shared<Algorithm>();
  ha->name = "test";
  ha->uses_host = true;
  ha->node = [](NodeContext& ctx) {
    if (ctx.rank() != 0) return;
    Comm& c = ctx.comm();
    c.send(c.host_rank(), 2, c.recv(c.host_rank(), 1));
  };
  ha->host = [n](NodeContext& ctx) {
    ctx.comm().send(0, 1, Bytes(std::size_t(n)));
    ctx.comm().recv(0, 2);
  };
  SimConfig h = sim_config("ipsc2", 2, Topology::Cube, Fidelity::Analytic);
  h.custom = ha;
  const auto before = run_simulation_isolated(h);
  ASSERT_EQ(before.value("status", ""), "ok") << before.dump();
  expect_rel(vtime(before), 2 * (1e-3 + n * 1e-6), 1e-12, "1 ms and 1 MB/s (the default link)");
  EXPECT_TRUE(before["what_if"].empty()) << before["what_if"].dump();

  h.overrides.host_latency_s = 275e-6;
  h.overrides.host_bandwidth_Bps = 2.8e6;
  const auto after = run_simulation_isolated(h);
  ASSERT_EQ(after.value("status", ""), "ok") << after.dump();
  const double one_way = 275e-6 + n / 2.8e6;
  expect_rel(vtime(after), 2 * one_way, 1e-12, "--host-latency 275us --host-bandwidth 2.8MBps");
  EXPECT_DOUBLE_EQ(after["what_if"]["host_latency_s"].get<double>(), 275e-6);
  EXPECT_DOUBLE_EQ(after["what_if"]["host_bandwidth_Bps"].get<double>(), 2.8e6);
  EXPECT_DOUBLE_EQ(after["model"]["host_startup_s"].get<double>(), 275e-6);
  EXPECT_DOUBLE_EQ(after["model"]["host_per_byte_s"].get<double>(), 1 / 2.8e6);
  // The node channels keep their figures.
  EXPECT_EQ(after["model"]["per_byte_s"], before["model"]["per_byte_s"]);
  EXPECT_EQ(after["model"]["startup_long_s"], before["model"]["startup_long_s"]);

  // The flow fidelity charges the bytes through SimGrid's host-up/host-down links, set alike.
  h.fidelity = Fidelity::Flow;
  const auto flow = run_simulation_isolated(h);
  ASSERT_EQ(flow.value("status", ""), "ok") << flow.dump();
  expect_rel(vtime(flow), 2 * one_way, 1e-9, "flow");
}

TEST(Collectives, DeliverTheRightDataOnRingsOfEverySize) {
  for (int P = 2; P <= 16; ++P) {
    auto r = run_custom(
        sim_config("ipsc860", P, Topology::Ring, Fidelity::Circuit), [](NodeContext& ctx) {
          Comm& c = ctx.comm();
          const int p = c.size(), k = c.rank();
          int bad = 0;
          for (int root : {0, p - 1, p / 2}) {
            bad += coll::broadcast(c, root, Bytes(k == root ? 9 : 0, 7)) != Bytes(9, 7);
            std::vector<Bytes> parts;
            if (k == root)
              for (int i = 0; i < p; ++i)
                parts.push_back(Bytes(std::size_t(i + 1), std::uint8_t(i)));
            bad += coll::scatterv(c, root, parts) != Bytes(std::size_t(k + 1), std::uint8_t(k));
            auto g = coll::gatherv(c, root, Bytes(std::size_t(k), 1));
            if (k == root)
              for (int i = 0; i < p; ++i)
                bad += g.at(i) != Bytes(std::size_t(i), 1);
            auto red = coll::reduce(c, root, std::vector<double>{double(k)}, coll::Op::Max);
            if (k == root) bad += red != std::vector<double>{double(p - 1)};
          }
          auto all = coll::allgatherv(c, Bytes(1, std::uint8_t(k)));
          for (int i = 0; i < p; ++i)
            bad += all.at(i) != Bytes(1, std::uint8_t(i));
          bad += coll::allreduce(c, std::vector<std::int64_t>{k}, coll::Op::Sum) !=
                 std::vector<std::int64_t>{p * (p - 1) / 2};
          bad += coll::prefix_sum(c, std::vector<std::int64_t>{2}) !=
                 std::vector<std::int64_t>{2 * (k + 1)};
          for (auto how : {coll::AllToAll::Direct, coll::AllToAll::Pairwise}) {
            std::vector<Bytes> out;
            for (int i = 0; i < p; ++i)
              out.push_back(Bytes(std::size_t(i % 3), std::uint8_t(k)));
            auto in = coll::alltoallv(c, out, how);
            for (int i = 0; i < p; ++i)
              bad += in.at(i) != Bytes(std::size_t(k % 3), std::uint8_t(i));
          }
          ctx.metrics()["bad"] = bad;
        });
    ASSERT_EQ(r["status"], "ok") << "P=" << P << " " << r.dump();
    for (const auto& n : r["per_node"])
      EXPECT_EQ(n["metrics"]["bad"], 0) << "ring P=" << P << " " << n.dump();
  }
}

TEST(Collectives, MoreClosedFormTimesUnderAnalytic) {
  // iPSC/860: two protocols and a per-hop term, so the forms are not all the same number.
  const NetworkParams& n = machine_spec("ipsc860").net;
  auto T = [&](double m, int h = 1) { return n.message_time(m, h); };
  for (int P : {2, 4, 16, 32}) {
    const int d = log2_exact(P);
    const std::string at = " P=" + std::to_string(P);
    auto cfg = sim_config("ipsc860", P, Topology::Cube, Fidelity::Analytic);
    const double b = 500; // block bytes
    // Scatter and gather: recursive halving / doubling, 2^i blocks of (12-byte header + b) at
    // the step over dimension i, plus a 4-byte count.
    double blocks = 0;
    for (int i = 0; i < d; ++i)
      blocks += T(4 + (1 << i) * (12 + b));
    expect_rel(vtime(run_custom(cfg,
                                [&](NodeContext& ctx) {
                                  std::vector<Bytes> parts;
                                  if (ctx.rank() == 0) parts.assign(P, Bytes(std::size_t(b)));
                                  coll::scatterv(ctx.comm(), 0, parts);
                                })),
               blocks, 1e-12, "scatterv" + at);
    expect_rel(
        vtime(run_custom(
            cfg, [&](NodeContext& ctx) { coll::gatherv(ctx.comm(), 0, Bytes(std::size_t(b))); })),
        blocks, 1e-12, "gatherv" + at);
    // Reduce (binomial tree) and prefix sum (recursive doubling): d messages of the vector.
    expect_rel(vtime(run_custom(cfg,
                                [&](NodeContext& ctx) {
                                  coll::reduce(ctx.comm(), 0, std::vector<double>(100, 1.0),
                                               coll::Op::Min);
                                })),
               d * T(800), 1e-12, "reduce" + at);
    expect_rel(vtime(run_custom(cfg,
                                [&](NodeContext& ctx) {
                                  coll::prefix_sum(ctx.comm(), std::vector<std::int64_t>(10, 1));
                                })),
               d * T(80), 1e-12, "prefix_sum" + at);
    // All-to-all, pairwise: step k exchanges with rank^k over popcount(k) hops.
    double pw = 0;
    for (int k = 1; k < P; ++k)
      pw += T(b, std::popcount(unsigned(k)));
    auto a2a = [&](coll::AllToAll how) {
      return vtime(run_custom(cfg, [&, how](NodeContext& ctx) {
        coll::alltoallv(ctx.comm(), std::vector<Bytes>(P, Bytes(std::size_t(b))), how);
      }));
    };
    expect_rel(a2a(coll::AllToAll::Pairwise), pw, 1e-12, "alltoall pairwise" + at);
    // Direct: every message at once, no contention: the farthest one ends it.
    expect_rel(a2a(coll::AllToAll::Direct), T(b, d), 1e-12, "alltoall direct" + at);
  }
  // Ring broadcast: two arms from the root, the longer one has P/2 neighbour steps.
  const NetworkParams& v = machine_spec("volvox").net;
  for (int P : {2, 5, 8, 16})
    expect_rel(vtime(run_custom(sim_config("volvox", P, Topology::Ring, Fidelity::Analytic),
                                [](NodeContext& ctx) {
                                  coll::broadcast(ctx.comm(), 1, Bytes(ctx.rank() == 1 ? 2000 : 0));
                                })),
               (P / 2) * v.message_time(2000, 1), 1e-12, "ring broadcast P=" + std::to_string(P));
}

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
