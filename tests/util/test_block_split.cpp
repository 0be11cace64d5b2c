// The block split (util/block_split.hpp): P parts of n items, contiguous, covering every item
// once, sizes within one of each other, and block_of the part that holds an item.
#include <gtest/gtest.h>

#include "util/block_split.hpp"

namespace zc {
namespace {

TEST(BlockSplit, PartsAreContiguousCoverEveryItemAndDifferByAtMostOne) {
  for (std::size_t n = 0; n <= 90; ++n)
    for (int P = 1; P <= 20; ++P) {
      std::size_t smallest = n, largest = 0, next = 0;
      for (int k = 0; k < P; ++k) {
        const BlockRange b = block_range(n, P, k);
        ASSERT_EQ(b.begin, next) << n << " items, " << P << " parts, part " << k;
        next = b.end;
        smallest = std::min(smallest, b.size());
        largest = std::max(largest, b.size());
      }
      EXPECT_EQ(next, n);
      EXPECT_LE(largest - smallest, 1u) << n << " items, " << P << " parts";
    }
}

TEST(BlockSplit, BlockOfIsThePartHoldingTheItem) {
  for (std::size_t n = 1; n <= 90; ++n)
    for (int P = 1; P <= 20; ++P)
      for (std::size_t i = 0; i < n; ++i) {
        const BlockRange b = block_range(n, P, block_of(n, P, i));
        ASSERT_TRUE(b.begin <= i && i < b.end) << "item " << i << " of " << n << ", " << P;
      }
  // i P / n would put row 38 of 77 in strip 0; strip 1 starts there.
  EXPECT_EQ(block_range(77, 2, 1).begin, 38u);
  EXPECT_EQ(block_of(77, 2, 38), 1);
}

TEST(BlockSplit, LargeCountsDoNotOverflow) {
  const std::size_t n = std::size_t(1) << 40;
  EXPECT_EQ(block_begin(n, 1024, 1023), n / 1024 * 1023);
  EXPECT_EQ(block_of(n, 1024, n - 1), 1023);
}

} // namespace
} // namespace zc
