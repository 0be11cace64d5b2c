// algo/charles/elastic_wire: Charles et al. §4's MultiScatter messages on the wire.
#include <gtest/gtest.h>

#include "algo/charles/elastic_wire.hpp"

using namespace zc;

// A message's bitmask reads back as the triangles it picked, word by word, for blocks that end
// inside a byte and inside an eight-byte word, and picking none.
TEST(ElasticWire, SelectionBitmaskReadsBackItsTriangles) {
  for (std::size_t n : {1u, 7u, 64u, 77u, 130u}) {
    const auto last = std::uint32_t(n - 1), half = std::uint32_t(n / 2);
    for (const auto& picked :
         std::vector<std::vector<std::uint32_t>>{{}, {0}, {last}, {0, 3, half, last}}) {
      std::vector<std::uint32_t> want;
      for (auto i : picked)
        if (i < n && (want.empty() || want.back() < i)) want.push_back(i); // ascending, once each
      const Bytes b = elastic::selection_header(n, want, 0);
      ASSERT_EQ(b.size(), (n + 7) / 8);
      RecordReader in(b, "test");
      EXPECT_EQ(elastic::read_selection(in, n), want) << n << " triangles";
    }
  }
}
