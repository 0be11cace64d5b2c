// Framebuffer edge cases found by the hostile review.
#include <cstring>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "raster/framebuffer.hpp"

using namespace zc;

TEST(Framebuffer, ZeroRowBandWithColouredBackground) {
  // More nodes than rows give empty bands; a non-grey background must not read row 0 of nothing.
  Framebuffer fb(8, RowSet::band(2, 2), glm::vec3(0, 0, 1));
  EXPECT_EQ(fb.rows().count(), 0);
  fb.clear(glm::vec3(1, 0, 0));
  Framebuffer interleaved(8, RowSet::interleaved(3, 4, 2), glm::vec3(0.2f, 0.5f, 1));
  EXPECT_EQ(interleaved.rows().count(), 0);
}

// Rows are filled with the background on first touch: whatever is read, packed, merged, copied or
// pasted must be what an eagerly cleared buffer holds.
TEST(Framebuffer, UntouchedRowsReadAsBackground) {
  const glm::vec3 bg(0.2f, 0.5f, 1);
  Framebuffer fb(5, RowSet::band(0, 4), bg);
  ASSERT_TRUE(fb.untouched(1));
  fb.ready_row(1);
  const std::uint8_t red[3] = {255, 0, 0};
  ASSERT_TRUE(fb.test_and_write(fb.index(2, 1), 0.5f, 7, red));
  EXPECT_FALSE(fb.untouched(1));
  EXPECT_TRUE(fb.untouched(2));

  // A copy keeps the untouched rows untouched; reading its planes fills them in.
  Framebuffer eager = fb;
  EXPECT_TRUE(eager.untouched(2));
  ASSERT_EQ(eager.depth().size(), 20u);
  EXPECT_FALSE(eager.untouched(2));
  EXPECT_EQ(eager.depth()[0], std::numeric_limits<float>::infinity());
  EXPECT_EQ(eager.ids()[fb.index(2, 1)], 7u);
  EXPECT_EQ(eager.rgb()[0], 51);
  EXPECT_EQ(eager.rgb()[2], 255);
  EXPECT_EQ(fb.pack_locations(3, 14), eager.pack_locations(3, 14));
  EXPECT_EQ(fb.covered(), 1u);

  // Merging a message that covers nothing leaves a row untouched; one that covers a pixel fills
  // the row in first.
  Framebuffer target(5, RowSet::band(0, 4), bg);
  target.merge_locations(fb.pack_locations(0, 20), 0);
  EXPECT_TRUE(target.untouched(0));
  EXPECT_FALSE(target.untouched(1));
  EXPECT_EQ(target.rgb(), eager.rgb());
  EXPECT_EQ(target.depth(), eager.depth());
  EXPECT_EQ(target.ids(), eager.ids());

  // Pasting and merging whole buffers give the eager results too.
  Framebuffer pasted(5, RowSet::all(4), bg);
  pasted.paste(fb);
  EXPECT_TRUE(pasted.untouched(3));
  EXPECT_EQ(pasted.rgb(), eager.rgb());
  Framebuffer merged(5, RowSet::all(4), bg);
  EXPECT_EQ(merged.merge(fb), 1u);
  EXPECT_EQ(merged.ids(), eager.ids());
}

// A message merged location by location with test_and_write, and with merge_locations (eight at a
// time where the CPU has AVX2): the same planes, ties on depth broken by the unsigned id (ids with
// the top bit set), NaN, signed zeros and infinities included, runs not a multiple of eight.
TEST(Framebuffer, MergeLocationsEqualsTestAndWriteAtEveryLocation) {
  const int W = 37, H = 5;
  std::mt19937 rng(7);
  const float specials[] = {0.f,
                            -0.f,
                            0.5f,
                            0.25f,
                            std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN(),
                            1.f};
  const std::uint32_t special_ids[] = {0u,          1u,          7u,         0x7fffffffu,
                                       0x80000000u, 0xfffffffeu, kNoTriangle};
  const auto fill = [&](Framebuffer& fb) {
    for (int y = 0; y < H; ++y) {
      fb.ready_row(y);
      for (int x = 0; x < W; ++x) {
        const std::uint8_t c[3] = {std::uint8_t(rng()), std::uint8_t(rng()), std::uint8_t(rng())};
        const std::size_t i = fb.index(x, y);
        fb.depth()[i] = specials[rng() % 7];
        fb.ids()[i] = special_ids[rng() % 7];
        std::memcpy(&fb.rgb()[3 * i], c, 3);
      }
    }
  };
  for (int trial = 0; trial < 40; ++trial) {
    Framebuffer target(W, RowSet::all(H), glm::vec3(0.1f, 0.2f, 0.3f));
    Framebuffer source = target;
    fill(target);
    fill(source);
    const std::size_t first = rng() % 20, n = W * H - first - rng() % 20;
    const auto msg = source.pack_locations(first, n);
    Framebuffer expect = target;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = first + k;
      expect.test_and_write(i, source.depth()[i], source.ids()[i], &source.rgb()[3 * i]);
    }
    ASSERT_EQ(target.merge_locations(msg, first), n);
    ASSERT_EQ(target.ids(), expect.ids()) << "trial " << trial;
    ASSERT_EQ(0, std::memcmp(target.depth().data(), expect.depth().data(), 4 * W * H));
    ASSERT_EQ(target.rgb(), expect.rgb()) << "trial " << trial;
  }
}
