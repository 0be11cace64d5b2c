// algo/kurc/kurc_partition: Kurc et al. §4's screen partitions (even split, RS, HBP) and their balance.
#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "algo/charles/elastic_partition.hpp"
#include "algo/kurc/kurc_partition.hpp"
#include "row_loads.hpp"
#include "util/load_imbalance.hpp"

using namespace zc;
using zc::test::bumpy_rows;

TEST(MergePartition, EvenSplitFollowsTheCubeDimensions) {
  auto o = even_split(16, 4);
  // First halving over bit 0, then bit 1.
  EXPECT_EQ(o, (std::vector<int>{0, 0, 0, 0, 2, 2, 2, 2, 1, 1, 1, 1, 3, 3, 3, 3}));
}

TEST(MergePartition, RecursiveSubdivisionMakesBandsOfEqualPixels) {
  auto rows = bumpy_rows(400, 3);
  for (int p : {2, 4, 8, 16}) {
    auto o = recursive_subdivision(rows, p);
    // Each node owns one contiguous band.
    for (int n = 0; n < p; ++n) {
      auto first = std::find(o.begin(), o.end(), n);
      auto last = std::find(o.rbegin(), o.rend(), n);
      ASSERT_NE(first, o.end());
      for (auto it = first; it != last.base(); ++it)
        ASSERT_EQ(*it, n);
    }
    EXPECT_LT(load_imbalance(node_loads(rows, o, p)), 0.5);
    EXPECT_LT(load_imbalance(node_loads(rows, o, p)),
              load_imbalance(node_loads(rows, even_split(400, p), p)));
  }
}

TEST(MergePartition, BinPackingBalancesBetterThanRecursiveSubdivision) {
  for (std::uint64_t seed : {1u, 2u, 3u})
    for (int p : {4, 8, 16, 32}) {
      auto rows = bumpy_rows(400, seed);
      const double rs = load_imbalance(node_loads(rows, recursive_subdivision(rows, p), p));
      const double hbp = load_imbalance(node_loads(rows, heuristic_bin_packing(rows, p), p));
      EXPECT_LE(hbp, rs) << "P=" << p;
    }
  EXPECT_DOUBLE_EQ(load_imbalance(std::vector<std::uint64_t>{5, 10, 15}), 1.0);
}
