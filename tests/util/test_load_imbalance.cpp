// The load imbalance measure (util/load_imbalance.hpp): Kurc et al.'s (max - min) / mean.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "util/load_imbalance.hpp"

namespace zc {
namespace {

TEST(LoadImbalance, IsMaxMinusMinOverTheMean) {
  EXPECT_DOUBLE_EQ(load_imbalance(std::vector<std::uint64_t>{5, 10, 15}), 1.0);
  EXPECT_DOUBLE_EQ(load_imbalance(std::vector<std::int64_t>{4, 4, 4, 4}), 0.0);
  EXPECT_DOUBLE_EQ(load_imbalance(std::vector<double>{0.0, 2.0}), 2.0);
}

TEST(LoadImbalance, IsZeroWhenNobodyWorked) {
  EXPECT_EQ(load_imbalance(std::vector<std::uint64_t>{}), 0.0);
  EXPECT_EQ(load_imbalance(std::vector<std::uint64_t>{0, 0, 0}), 0.0);
  EXPECT_EQ(load_imbalance(std::vector<double>{0.0}), 0.0);
}

} // namespace
} // namespace zc
