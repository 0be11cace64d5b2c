// algo/charles/elastic_partition: Charles et al. §5's rows of equal estimated load.
#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "algo/charles/elastic_partition.hpp"
#include "algo/kurc/kurc_partition.hpp"
#include "row_loads.hpp"
#include "util/load_imbalance.hpp"

using namespace zc;
using zc::test::bumpy_rows;

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

// The boundaries found in one walk over the rows are those of a binary search per boundary (the
// rule the walk replaces), with more slices than rows and with empty rows.
TEST(ElasticPartition, OneWalkFindsTheBinarySearchBoundaries) {
  const auto searched = [](const std::vector<std::int64_t>& load, int parts) {
    const int h = int(load.size());
    std::vector<std::int64_t> cum(std::size_t(h) + 1, 0);
    for (int y = 0; y < h; ++y)
      cum[y + 1] = cum[y] + load[y];
    std::vector<int> b(std::size_t(parts) + 1, 0);
    b[parts] = h;
    for (int k = 1; k < parts; ++k) {
      const std::int64_t target = std::int64_t(k) * cum[h];
      auto it = std::lower_bound(cum.begin() + b[k - 1], cum.end(), target,
                                 [&](std::int64_t c, std::int64_t t) { return c * parts < t; });
      int y = int(it - cum.begin());
      if (y > b[k - 1] &&
          std::llabs(cum[y - 1] * parts - target) <= std::llabs(cum[y] * parts - target))
        --y;
      b[k] = std::min(y, h);
    }
    return b;
  };
  for (int parts : {2, 3, 16, 64, 512, 1024}) {
    auto rows = bumpy_rows(256, parts);
    std::vector<std::int64_t> load(rows.begin(), rows.end());
    for (int y = 0; y < 256; y += 7)
      load[std::size_t(y)] = 0;
    EXPECT_EQ(elastic_partition(load, parts), searched(load, parts)) << parts << " slices";
  }
}
