// Messages charged as the modelled program's records (comm/comm.hpp): a payload of M bytes charged
// as N takes the time of N bytes on every fidelity, the charged size reaches the receiver and the
// collectives that forward it, and the report states charged and payload bytes per phase.
#include <gtest/gtest.h>

#include "comm/collectives.hpp"
#include "machine/machine.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

// Node 0 sends node `to` a payload of `payload` bytes charged as `charged`.
nlohmann::json one_message(Fidelity f, int to, std::size_t payload, std::size_t charged) {
  return run_custom(sim_config("ipsc860", 8, Topology::Cube, f), [=](NodeContext& ctx) {
    auto ph = ctx.phase("exchange");
    if (ctx.rank() == 0) ctx.comm().send(to, 5, Message{Bytes(payload, 7), charged});
    if (ctx.rank() == to) {
      const Message m = ctx.comm().recv_message(0, 5);
      EXPECT_EQ(m.payload.size(), payload);
      EXPECT_EQ(m.charged, charged);
    }
  });
}

} // namespace

TEST(ChargedMessages, TakeTheTimeOfTheirChargedSizeOnEveryFidelity) {
  const NetworkParams& n = machine_spec("ipsc860").net;
  for (Fidelity f : {Fidelity::Analytic, Fidelity::Circuit, Fidelity::Flow}) {
    const std::string at = " fidelity " + std::to_string(int(f));
    // 3 hops (node 0 to node 7): 64 bytes of payload charged as 5,000, and the reverse.
    expect_rel(vtime(one_message(f, 7, 64, 5000)), n.message_time(5000, 3), 1e-9, "M<N" + at);
    expect_rel(vtime(one_message(f, 7, 5000, 64)), n.message_time(64, 3), 1e-9, "M>N" + at);
    // Bytes sent without a charged size: charged as the payload's size, as before.
    expect_rel(vtime(run_custom(sim_config("ipsc860", 8, Topology::Cube, f),
                                [](NodeContext& ctx) {
                                  if (ctx.rank() == 0) ctx.comm().send(7, 5, Bytes(5000));
                                  if (ctx.rank() == 7) ctx.comm().recv(0, 5);
                                })),
               n.message_time(5000, 3), 1e-9, "charged as payload" + at);
  }
}

TEST(ChargedMessages, ACollectiveForwardingBlocksChargesTheirChargedSum) {
  const NetworkParams& n = machine_spec("ipsc860").net;
  auto T = [&](double m) { return n.message_time(m, 1); };
  for (int P : {2, 8, 16}) {
    const int d = log2_exact(P);
    const std::string at = " P=" + std::to_string(P);
    auto cfg = sim_config("ipsc860", P, Topology::Cube, Fidelity::Analytic);
    // Gather: 2^i blocks at the step over dimension i, each charged 500 bytes (its payload: 10)
    // plus its 12 bytes of framing, and the message's 4-byte count.
    double blocks = 0;
    for (int i = 0; i < d; ++i)
      blocks += T(4 + (1 << i) * (12 + 500.0));
    auto r = run_custom(cfg, [&](NodeContext& ctx) {
      auto got = coll::gatherv(ctx.comm(), 0, Message{Bytes(10, 1), 500});
      if (ctx.rank() == 0)
        for (const auto& m : got) {
          EXPECT_EQ(m.payload.size(), 10u);
          EXPECT_EQ(m.charged, 500u);
        }
    });
    expect_rel(vtime(r), blocks, 1e-12, "gatherv" + at);
    // All-gather by recursive doubling: every node ends with every block's charged size.
    double doubling = 0;
    for (int i = 0; i < d; ++i)
      doubling += T(4 + (1 << i) * (12 + 300.0));
    expect_rel(
        vtime(run_custom(cfg,
                         [&](NodeContext& ctx) {
                           auto all = coll::allgatherv(ctx.comm(), Message{Bytes(3, 1), 300});
                           for (const auto& m : all)
                             EXPECT_EQ(m.charged, 300u);
                         })),
        doubling, 1e-12, "allgatherv" + at);
  }
}

TEST(ChargedMessages, TheReportStatesChargedAndPayloadBytesPerPhase) {
  auto r = one_message(Fidelity::Analytic, 1, 64, 5000);
  ASSERT_EQ(r["status"], "ok") << r.dump();
  EXPECT_EQ(r["communication"]["bytes"], 5000);
  EXPECT_EQ(r["communication"]["payload_bytes"], 64);
  EXPECT_EQ(r["per_node"][0]["bytes_sent"], 5000);
  EXPECT_EQ(r["per_node"][0]["payload_bytes_sent"], 64);
  ASSERT_EQ(r["phases"].size(), 1u);
  EXPECT_EQ(r["phases"][0]["name"], "exchange");
  EXPECT_EQ(r["phases"][0]["charged_bytes"], 5000);
  EXPECT_EQ(r["phases"][0]["payload_bytes"], 64);
  EXPECT_EQ(r["phases"][0]["messages"], 1);
}
