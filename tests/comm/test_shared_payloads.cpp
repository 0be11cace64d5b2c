// Message payloads are shared, not copied (comm/payload.hpp): a broadcast hands every node the
// root's buffer, a multi-broadcast or a gather forwards the blocks it received as they are, while
// the network is still charged every hop (test_charged_messages.cpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>

#include "comm/collectives.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error("not shared: " + what);
}

// All simulated nodes run in one process (the forked child of run_custom), so a buffer's address
// seen by every node says whether they share it.
Bytes block_of(int rank) {
  return Bytes(std::size_t(100 + rank), std::uint8_t(rank));
}

} // namespace

TEST(Payload, TakeMovesTheOnlyHoldersBytesAndCopiesSharedOnes) {
  Payload p(Bytes(1000, 3));
  const std::uint8_t* at = p.data();
  Payload q = p; // shared: a reference, not a copy
  EXPECT_TRUE(q.shares(p));
  EXPECT_EQ(q.data(), at);
  EXPECT_EQ(p.holders(), 2);
  Bytes copy = std::move(q).take();
  EXPECT_NE(copy.data(), at);
  EXPECT_EQ(copy, Bytes(1000, 3));
  Bytes moved = std::move(p).take();
  EXPECT_EQ(moved.data(), at);
  EXPECT_EQ(Payload().size(), 0u);
  EXPECT_TRUE(Payload(Bytes{}).empty());
}

TEST(SharedPayloads, CollectivesHandEveryNodeTheSendersBuffer) {
  for (Topology topo : {Topology::Cube, Topology::Ring}) {
    const int P = 16;
    std::vector<const std::uint8_t*> sent(P, nullptr);
    const std::uint8_t* broadcast_at = nullptr;
    auto r = run_custom(sim_config("ipsc860", P, topo, Fidelity::Analytic), [&](NodeContext& ctx) {
      Comm& c = ctx.comm();
      const int me = c.rank();
      Message root{Bytes(5000, 9), 5000};
      const std::uint8_t* root_at = root.payload.data();
      if (me == 3) broadcast_at = root_at;
      const Message got = coll::broadcast(c, 3, std::move(root), 50);
      coll::barrier(c, 51);
      require(got.payload.data() == broadcast_at && got.payload == Bytes(5000, 9), "broadcast");

      Message mine{block_of(me), 7};
      sent[std::size_t(me)] = mine.payload.data();
      auto all = coll::allgatherv(c, std::move(mine), 52);
      for (int k = 0; k < P; ++k)
        require(all[std::size_t(k)].payload.data() == sent[std::size_t(k)] &&
                    all[std::size_t(k)].payload == block_of(k) && all[std::size_t(k)].charged == 7,
                "allgatherv block " + std::to_string(k));

      auto gathered = coll::gatherv(c, 0, all[std::size_t(me)], 53);
      if (me == 0)
        for (int k = 0; k < P; ++k)
          require(gathered[std::size_t(k)].payload.data() == sent[std::size_t(k)], "gatherv");

      std::vector<Message> parts;
      if (me == 0)
        for (int k = 0; k < P; ++k)
          parts.push_back(all[std::size_t(k)]);
      const Message part = coll::scatterv(c, 0, std::move(parts), 54);
      require(part.payload.data() == sent[std::size_t(me)], "scatterv");
    });
    EXPECT_EQ(r["status"], "ok") << (topo == Topology::Cube ? "cube: " : "ring: ") << r.dump();
  }
}

// A payload of runs (the rows a node never drew, as their background) stands for its whole string:
// its size, its bytes, its equality and take() are the whole string's; only a reader that asks
// for its runs sees them.
TEST(Payload, MadeOfRepeatedRunsReadsAsTheWholeString) {
  const std::uint8_t bg[3] = {1, 2, 3};
  const Bytes head = {9, 9};
  RunBytes r;
  r.append(head.data(), head.size());
  r.append_fill(bg, 3, 6);
  const Bytes whole = {9, 9, 1, 2, 3, 1, 2, 3};
  Payload p(r);
  ASSERT_NE(p.runs(), nullptr);
  EXPECT_EQ(p.size(), whole.size());
  EXPECT_EQ(p.bytes(), whole);
  EXPECT_TRUE(p == Payload(whole));
  Payload q = p;
  EXPECT_TRUE(q.shares(p));
  EXPECT_EQ(p.holders(), 2);
  EXPECT_EQ(std::move(q).take(), whole);
  // Without a repeated run it is plain bytes.
  RunBytes plain;
  plain.append(head.data(), head.size());
  const Payload b(std::move(plain));
  EXPECT_EQ(b.runs(), nullptr);
  EXPECT_EQ(b.bytes(), head);
}
