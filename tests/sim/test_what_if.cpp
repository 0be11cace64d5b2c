// sim: what-if flags change the formula and the report states them.
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

TEST(WhatIfs, WhatIfFlagsChangeTheFormula) {
  RunConfig c = sim_config("ipsc860", 8, Topology::Cube, Fidelity::Analytic);
  c.what_ifs.set("latency", {1e-3});
  c.what_ifs.set("bandwidth", {1e6});
  c.what_ifs.set("per-hop", {50e-6});
  auto t = one_way(c, "1,7", "10B,1000B");
  expect_rel(t.at({10.0, 1}), 1e-3 + 10e-6, 1e-12, "short");
  expect_rel(t.at({1000.0, 3}), 1e-3 + 1000e-6 + 2 * 50e-6, 1e-12, "long, 3 hops");
  // The flow model reads the bandwidth from its links: the override must reach them too.
  c.fidelity = Fidelity::Flow;
  auto f = one_way(c, "7", "1000B");
  expect_rel(f.at({1000.0, 3}), 1e-3 + 1000e-6 + 2 * 50e-6, 1e-12, "flow");
  // --cpu-scale multiplies the CPU and nothing else.
  RunConfig s = sim_config("ipsc2", 1, Topology::Cube, Fidelity::Circuit);
  s.algorithm = "sequential";
  s.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";
  s.width = s.height = 96;
  const double t1 = vtime(run_simulation_isolated(s));
  s.what_ifs.set("cpu-scale", {0.25});
  expect_rel(vtime(run_simulation_isolated(s)), 0.25 * t1, 1e-12, "cpu-scale");
}

// --latency x0.1 on the iPSC/860 keeps its two message protocols (docs/machines.md), each start-up
// a tenth, against the closed form start-up(bytes) + bytes * per-byte + (hops - 1) * per-hop;
// --bandwidth x2 halves the per-byte cost. An absolute --latency gives both sizes one start-up.
TEST(WhatIfs, RelativeWhatIfsKeepEveryProtocolAgainstTheClosedForm) {
  const NetworkParams n = machine_spec("ipsc860").net;
  ASSERT_NE(n.startup_short_s, n.startup_long_s);
  for (const Fidelity fid : {Fidelity::Analytic, Fidelity::Circuit}) {
    RunConfig c = sim_config("ipsc860", 8, Topology::Cube, fid);
    c.what_ifs.set("latency", {0.1, true});
    c.what_ifs.set("bandwidth", {2, true});
    const auto t = one_way(c, "1,7", "10B,1000B");
    const double per_byte = n.per_byte_s / 2;
    expect_rel(t.at({10.0, 1}), 0.1 * n.startup_short_s + 10 * per_byte, 1e-12, "short, x0.1");
    expect_rel(t.at({1000.0, 3}), 0.1 * n.startup_long_s + 1000 * per_byte + 2 * n.per_hop_s, 1e-12,
               "long, 3 hops, x0.1");
    c.what_ifs.set("latency", {7.5e-6, false});
    const auto a = one_way(c, "1", "10B,1000B");
    expect_rel(a.at({10.0, 1}), 7.5e-6 + 10 * per_byte, 1e-12, "short, 7.5us");
    expect_rel(a.at({1000.0, 1}), 7.5e-6 + 1000 * per_byte, 1e-12, "long, 7.5us");
  }
}

// A report says which model made its times: the what-ifs in force, every CPU cost (scaled), the
// host link, and every option of the algorithm with its default.
TEST(WhatIfs, TheReportStatesTheWhatIfsCpuCostsAndOptions) {
  RunConfig s = sim_config("ipsc860", 2, Topology::Cube, Fidelity::Circuit);
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
  s.what_ifs.set("cpu-scale", {0.5});
  s.what_ifs.set("latency", {20e-6});
  const auto w = run_simulation_isolated(s);
  ASSERT_EQ(w.value("status", ""), "ok") << w.dump();
  EXPECT_DOUBLE_EQ(w["what_if"]["cpu_scale"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(w["what_if"]["latency_s"].get<double>(), 20e-6);
  EXPECT_FALSE(w["what_if"].contains("bandwidth_Bps"));
  expect_rel(w["model"]["cpu_seconds"]["vertices_transformed"].get<double>(), 0.5 * vt, 1e-12,
             "cpu-scale in the report");
}

// --host-latency and --host-bandwidth (docs/machines.md, the host link): a host-to-node-0 message
// of n bytes takes host start-up + n / host bandwidth under the analytic fidelity, before and after
// the what-if, and node 0's answer back as long; the report names them; the node channels keep
// their figures.
TEST(WhatIfs, HostLinkWhatIfsGiveTheHostMessagesClosedForm) {
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
  RunConfig h = sim_config("ipsc2", 2, Topology::Cube, Fidelity::Analytic);
  h.custom = ha;
  const auto before = run_simulation_isolated(h);
  ASSERT_EQ(before.value("status", ""), "ok") << before.dump();
  expect_rel(vtime(before), 2 * (1e-3 + n * 1e-6), 1e-12, "1 ms and 1 MB/s (the default link)");
  EXPECT_TRUE(before["what_if"].empty()) << before["what_if"].dump();

  h.what_ifs.set("host-latency", {275e-6});
  h.what_ifs.set("host-bandwidth", {2.8e6});
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
