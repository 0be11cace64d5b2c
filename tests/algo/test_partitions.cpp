// Work partitions: Charles et al. §5 (elastic rows) and Kurc et al. §4 (RS, HBP).
#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "algo/elastic_partition.hpp"
#include "algo/kurc_partition.hpp"
#include "util/load_imbalance.hpp"

using namespace zc;

namespace {
std::vector<std::uint64_t> bumpy_rows(int h, std::uint64_t seed) {
  std::vector<std::uint64_t> r(h);
  std::uint64_t s = seed;
  for (int y = 0; y < h; ++y) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    const double bump = (y > h / 4 && y < h / 2) ? 300 : 20;
    r[y] = std::uint64_t(bump * double(s >> 40) / double(1 << 24));
  }
  return r;
}
} // namespace

TEST(ElasticPartition, DifferenceArrayCountsTrianglesPerRow) {
  // Rows 2..4, 3..3, 0..9 (clamped), and one off-screen triangle.
  std::vector<RowExtent> e{{2, 4}, {3, 3}, {-5, 20}, {12, 14}};
  auto load = scan_load(load_differences(e, 10), 10);
  EXPECT_EQ(load, (std::vector<std::int64_t>{1, 1, 2, 3, 2, 1, 1, 1, 1, 1}));
}

TEST(ElasticPartition, SlicesWithinOneRowOfTheIdeal) {
  for (int parts : {1, 2, 3, 4, 7, 8, 16, 32}) {
    auto rows = bumpy_rows(256, parts);
    std::vector<std::int64_t> load(rows.begin(), rows.end());
    auto b = elastic_partition(load, parts);
    ASSERT_EQ(int(b.size()), parts + 1);
    EXPECT_EQ(b.front(), 0);
    EXPECT_EQ(b.back(), 256);
    const std::int64_t total = std::accumulate(load.begin(), load.end(), std::int64_t(0));
    const std::int64_t maxrow = *std::max_element(load.begin(), load.end());
    for (int k = 0; k < parts; ++k) {
      ASSERT_LE(b[k], b[k + 1]);
      std::int64_t s = 0;
      for (int y = b[k]; y < b[k + 1]; ++y)
        s += load[y];
      EXPECT_LE(std::llabs(s * parts - total), maxrow * parts) << parts << " slice " << k;
    }
  }
}

TEST(ElasticPartition, AllLoadOnOneRowAndEmptyLoad) {
  std::vector<std::int64_t> one(64, 0);
  one[40] = 1000;
  auto b = elastic_partition(one, 4);
  EXPECT_EQ(b.front(), 0);
  EXPECT_EQ(b.back(), 64);
  EXPECT_TRUE(std::is_sorted(b.begin(), b.end()));
  auto e = elastic_partition(std::vector<std::int64_t>(64, 0), 4);
  EXPECT_EQ(e, (std::vector<int>{0, 16, 32, 48, 64}));
}

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
