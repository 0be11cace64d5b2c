// comm: FIFO order per source and tag, any-source receives and the host as a rank.
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

TEST(Comm, FifoPerSourceAndTagAnySourceAndTheHostAsARank) {
  RunConfig c = sim_config("ipsc2", 8, Topology::Cube, Fidelity::Flow);
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
  RunConfig h = sim_config("ipsc860", 8, Topology::Cube, Fidelity::Analytic);
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
