// The Volvox's T800 links carry 1.7 MB/s one way and 2.35 MB/s in all with both directions busy
// (docs/machines.md): message times against those closed forms under every fidelity; the iPSC's
// DCM channels stay full duplex.
#include <gtest/gtest.h>
#include <simgrid/s4u.hpp>

#include "machine/machine.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

constexpr double kBytes = 200000;
const Fidelity kAll[] = {Fidelity::Analytic, Fidelity::Flow, Fidelity::Circuit};

// Nodes 0 and 1 (neighbours) send kBytes to each other, the second one `delay` seconds later, or
// only node 0 sends when `both` is false. Returns the virtual time of the run.
double exchange(const std::string& machine, Fidelity f, bool both, double delay = 0,
                WhatIfs o = {}) {
  RunConfig cfg = sim_config(machine, 2, Topology::Ring, f);
  cfg.what_ifs = o;
  const auto r = run_custom(cfg, [=](NodeContext& ctx) {
    Comm& c = ctx.comm();
    const int other = 1 - c.rank();
    if (c.rank() == 1 && !both) {
      c.recv(0, 0);
      return;
    }
    if (c.rank() == 1 && delay > 0) simgrid::s4u::this_actor::sleep_for(delay);
    auto h = c.isend(other, 0, Bytes(std::size_t(kBytes)));
    if (both) c.recv(other, 0);
    h->wait();
  });
  EXPECT_EQ(r["status"], "ok") << r.dump();
  return r["virtual_time_s"].get<double>();
}

} // namespace

TEST(DuplexLinks, OneWayTransferAtTheOneWayRate) {
  const NetworkParams& n = machine_spec("volvox").net;
  for (Fidelity f : kAll)
    expect_rel(exchange("volvox", f, false), n.startup(kBytes) + kBytes / 1.7e6, 1e-9,
               fidelity_name(f));
}

TEST(DuplexLinks, ExchangeWithBothDirectionsBusyAtHalfTheTwoWayRate) {
  const NetworkParams& n = machine_spec("volvox").net;
  for (Fidelity f : kAll)
    expect_rel(exchange("volvox", f, true), n.startup(kBytes) + kBytes / 1.175e6, 1e-9,
               fidelity_name(f));
}

TEST(DuplexLinks, IpscChannelsStayFullDuplex) {
  const NetworkParams& n = machine_spec("ipsc2").net;
  for (Fidelity f : kAll)
    expect_rel(exchange("ipsc2", f, true), n.message_time(kBytes, 1), 1e-9, fidelity_name(f));
}

// Node 1 starts `d` later: node 0's bytes go alone at 1.7 MB/s for d, then both directions at
// 1.175 MB/s until node 0's are across, then node 1's last 1.7 MB/s x d bytes alone again.
TEST(DuplexLinks, StaggeredExchangeSpeedsUpWhenOneDirectionFinishes) {
  const NetworkParams& n = machine_spec("volvox").net;
  const double d = 0.02, s = n.startup(kBytes);
  const double want = s + 2 * d + (kBytes - 1.7e6 * d) / 1.175e6;
  for (Fidelity f : kAll)
    expect_rel(exchange("volvox", f, true, d), want, 1e-9, fidelity_name(f));
}

// A what-if link twice as fast one way is twice as fast both ways: 4.7 MB/s in all.
TEST(DuplexLinks, WhatIfBandwidthScalesTheTwoWayTotal) {
  const NetworkParams& n = machine_spec("volvox").net;
  WhatIfs o;
  o.set("bandwidth", {3.4e6});
  for (Fidelity f : kAll)
    expect_rel(exchange("volvox", f, true, 0, o), n.startup(kBytes) + kBytes / 2.35e6, 1e-9,
               fidelity_name(f));
}

// Store-and-forward on a 4-node ring: node 0 sends to node 2 (hops 0->1, 1->2) while node 1 sends
// to node 0. The first hop shares link 0-1 with node 1's message (1.175 MB/s each way); the
// second hop has link 1-2 to itself (1.7 MB/s).
TEST(DuplexLinks, EachStoreAndForwardHopSeesOnlyItsOwnLink) {
  const NetworkParams& n = machine_spec("volvox").net;
  const double s = n.startup(kBytes);
  for (Fidelity f : kAll) {
    const auto r = run_custom(sim_config("volvox", 4, Topology::Ring, f), [](NodeContext& ctx) {
      Comm& c = ctx.comm();
      if (c.rank() == 0) c.send(2, 0, Bytes(std::size_t(kBytes)));
      if (c.rank() == 1) c.send(0, 1, Bytes(std::size_t(kBytes)));
      if (c.rank() == 0) c.recv(1, 1);
      if (c.rank() == 2) c.recv(0, 0);
    });
    ASSERT_EQ(r["status"], "ok") << r.dump();
    expect_rel(r["virtual_time_s"].get<double>(), 2 * s + kBytes / 1.175e6 + kBytes / 1.7e6, 1e-9,
               fidelity_name(f));
  }
}
