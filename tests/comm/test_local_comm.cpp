// comm/local_comm: the in-process Comm keeps the interface's matching rules (by source and tag,
// any source, one stream per source and tag in send order, the host as rank size()) and turns a
// deadlock or a failing rank into an error instead of a hang.
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "comm/local_comm.hpp"
#include "comm/wire.hpp"

using namespace zc;

TEST(LocalComm, OneStreamPerSourceAndTagInSendOrder) {
  std::vector<int> bad(2, 0);
  run_local(2, Topology::Cube, [&](Comm& c) {
    if (c.rank() == 0) {
      for (int i = 0; i < 50; ++i) {
        c.isend(1, 5, Bytes(std::size_t(1 + i), std::uint8_t(i)))->wait();
        c.send(1, 6, Bytes(1, std::uint8_t(100 + i)));
      }
      return;
    }
    for (int i = 0; i < 50; ++i) // tag 6 first: tags are independent streams
      bad[1] += c.recv(0, 6) != Bytes(1, std::uint8_t(100 + i));
    for (int i = 0; i < 50; ++i)
      bad[1] += c.recv(kAnySource, 5) != Bytes(std::size_t(1 + i), std::uint8_t(i));
  });
  EXPECT_EQ(bad, (std::vector<int>{0, 0}));
}

TEST(LocalComm, AnySourceSaysWhoSentAndASourceTakesOnlyItsOwn) {
  const int P = 7;
  std::vector<int> seen(P, 0);
  int mismatched = 0;
  run_local(P, Topology::Ring, [&](Comm& c) {
    if (c.rank() != 0) {
      c.send(0, 3, pack(std::vector<std::int32_t>{c.rank()}));
      c.send(0, 4, pack(std::vector<std::int32_t>{-c.rank()}));
      return;
    }
    // Tag 4 from the last rank first: the other ranks' tag-4 messages wait meanwhile.
    mismatched += unpack<std::int32_t>(c.recv(P - 1, 4)).at(0) != -(P - 1);
    for (int k = 1; k < P; ++k) {
      int from = -1;
      mismatched += unpack<std::int32_t>(c.recv(kAnySource, 3, &from)).at(0) != from;
      seen.at(std::size_t(from))++;
    }
    for (int k = 1; k < P - 1; ++k)
      mismatched += unpack<std::int32_t>(c.recv(k, 4)).at(0) != -k;
  });
  EXPECT_EQ(mismatched, 0);
  EXPECT_EQ(seen, (std::vector<int>{0, 1, 1, 1, 1, 1, 1}));
}

TEST(LocalComm, TheHostIsRankSizeAndChargedSizesTravel) {
  std::atomic<int> bad = 0;
  run_local(4, Topology::Cube,
            [&](Comm& c) {
              if (c.is_host()) {
                c.send(3, 9, Message{Bytes(10, 1), 77});
                bad += c.recv_message(3, 9).charged != 5;
                return;
              }
              bad += c.dimension() != 2 || c.neighbour(1) != (c.rank() ^ 2);
              if (c.rank() != 3) return;
              Message m = c.recv_message(c.host_rank(), 9);
              bad += m.charged != 77 || m.payload.size() != 10;
              c.send(c.host_rank(), 9, Message{std::move(m.payload), 5});
            },
            {.host = true});
  EXPECT_EQ(bad, 0);
}

TEST(LocalComm, BlocksArriveWhole) {
  int bad = 0;
  run_local(2, Topology::Ring, [&](Comm& c) {
    if (c.rank() == 0) {
      c.send_blocks(1, 2, {{0, Message{Bytes(3, 7), 1}}, {5, charged_as_payload(Bytes{})}});
      return;
    }
    Blocks b = c.recv_blocks(0, 2);
    bad += b.size() != 2 || b[0].owner != 0 || b[0].data.payload != Bytes(3, 7) ||
           b[0].data.charged != 1 || b[1].owner != 5 || !b[1].data.payload.empty();
  });
  EXPECT_EQ(bad, 0);
}

TEST(LocalComm, AFailingRankFailsTheRunAndWakesTheWaitingOnes) {
  try {
    run_local(4, Topology::Cube, [](Comm& c) {
      if (c.rank() == 2) throw std::runtime_error("rank 2 gave up");
      c.recv(2, 1); // never sent
    });
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "rank 2 gave up");
  }
}

TEST(LocalComm, ADeadlockIsAnErrorNamingTheReceive) {
  try {
    run_local(2, Topology::Ring, [](Comm& c) { c.recv(1 - c.rank(), 8); },
              {.deadlock_after_s = 0.05});
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("tag 8"), std::string::npos) << e.what();
  }
}

TEST(LocalComm, RanksOutsideTheRunAreRefused) {
  EXPECT_THROW(run_local(3, Topology::Cube, [](Comm&) {}), std::invalid_argument);
  EXPECT_THROW(run_local(2, Topology::Ring, [](Comm& c) { c.send(2, 1, Bytes{}); }),
               std::invalid_argument);
  EXPECT_THROW(run_local(2, Topology::Ring, [](Comm& c) { c.recv(-3, 1); }), std::invalid_argument);
}
