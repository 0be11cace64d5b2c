// Node groups as a Comm of their own: the collectives run unchanged within each group.
#include <gtest/gtest.h>

#include "comm/collectives.hpp"
#include "compositing/group.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

TEST(GroupComm, DigitGroupsOfMixedRadix) {
  using compositing::digit_group;
  EXPECT_EQ(digit_group(5, {2, 3, 2}, 0), (std::vector<int>{4, 5}));
  EXPECT_EQ(digit_group(5, {2, 3, 2}, 1), (std::vector<int>{1, 3, 5}));
  EXPECT_EQ(digit_group(5, {2, 3, 2}, 2), (std::vector<int>{5, 11}));
}

TEST(GroupComm, CollectivesWithinEachGroupSeeOnlyTheGroup) {
  for (auto [P, topo] : {std::pair{12, Topology::Ring}, std::pair{16, Topology::Cube}}) {
    RunConfig c = sim_config("ipsc2", P, topo, Fidelity::Circuit);
    const std::vector<int> factors = P == 12 ? std::vector<int>{4, 3} : std::vector<int>{4, 4};
    auto r = run_custom(c, [&](NodeContext& ctx) {
      for (int digit = 0; digit < 2; ++digit) {
        compositing::GroupComm g(ctx.comm(), compositing::digit_group(ctx.rank(), factors, digit));
        EXPECT_EQ(g.topology() == Topology::Cube, topo == Topology::Cube);
        const auto sum = coll::allreduce(g, std::vector<std::int64_t>{ctx.rank()}, coll::Op::Sum);
        std::int64_t want = 0;
        for (int m : g.members())
          want += m;
        EXPECT_EQ(sum[0], want);
        auto all = coll::allgatherv(g, Bytes{std::uint8_t(ctx.rank())});
        for (int k = 0; k < g.size(); ++k)
          EXPECT_EQ(all[std::size_t(k)], Bytes{std::uint8_t(g.world_rank(k))});
      }
    });
    EXPECT_EQ(r["status"], "ok") << r.dump();
  }
}
