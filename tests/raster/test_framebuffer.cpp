// Framebuffer edge cases found by the hostile review.
#include <cstring>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "raster/framebuffer.hpp"
#include "raster/image_io.hpp"

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

// A band packed as runs (the rows not touched yet as their planes' backgrounds) is the packed
// string, and merging it gives what merging the string gives, rows the message does not cover left
// untouched; so does a hand-made message whose covered row has a repeated colour plane (written out
// to be merged).
TEST(Framebuffer, LocationRunsArePackedLocations) {
  const int W = 13, H = 6;
  const glm::vec3 bg(0.2f, 0.5f, 1);
  std::mt19937 rng(11);
  Framebuffer source(W, RowSet::all(H), bg);
  for (int y : {1, 2, 4}) {
    source.ready_row(y);
    for (int x = 0; x < W; x += 1 + int(rng() % 3)) {
      const std::uint8_t c[3] = {std::uint8_t(rng()), std::uint8_t(rng()), std::uint8_t(rng())};
      source.test_and_write(source.index(x, y), float(rng() % 100) / 100.f, rng() % 50, c);
    }
  }
  ASSERT_TRUE(source.untouched(0));
  ASSERT_TRUE(source.untouched(3));
  for (std::size_t first : {0u, 5u, 13u, 26u})
    for (std::size_t n : {1u, 13u, 20u, 39u}) {
      if (first + n > std::size_t(W * H)) continue;
      const RunBytes runs = source.pack_location_runs(first, n);
      const Bytes bytes = source.pack_locations(first, n);
      ASSERT_EQ(runs.whole(), bytes) << first << "+" << n;
      Framebuffer a(W, RowSet::all(H), bg), b(W, RowSet::all(H), bg);
      a.ready_row(2); // a target row already drawn (background there too)
      b.ready_row(2);
      ASSERT_EQ(a.merge_locations(runs, 0, runs.size(), first), n);
      ASSERT_EQ(b.merge_locations(bytes, first), n);
      for (int y = 0; y < H; ++y)
        EXPECT_EQ(a.untouched(y), b.untouched(y)) << "row " << y;
      EXPECT_TRUE(a.untouched(3));
      EXPECT_EQ(a.rgb(), b.rgb());
      EXPECT_EQ(a.ids(), b.ids());
      EXPECT_EQ(0, std::memcmp(a.depth().data(), b.depth().data(), 4 * W * H));
    }
  // One row whose colours are a repeated run but whose ids are not: merged from its written-out
  // planes, at an offset into the message.
  const std::uint8_t grey[3] = {40, 40, 40}, pad = 0;
  RunBytes msg;
  msg.append_fill(&pad, 1, 5);
  msg.append_fill(grey, 3, 3 * W);
  Bytes zs(4 * W), ids(4 * W);
  for (int x = 0; x < W; ++x) {
    const float z = 0.5f;
    const std::uint32_t id = x % 2 ? kNoTriangle : std::uint32_t(x);
    std::memcpy(&zs[4 * x], &z, 4);
    std::memcpy(&ids[4 * x], &id, 4);
  }
  msg.append(zs.data(), zs.size());
  msg.append(ids.data(), ids.size());
  Framebuffer a(W, RowSet::all(H), bg), b(W, RowSet::all(H), bg);
  ASSERT_EQ(a.merge_locations(msg, 5, 11 * W, 3 * W), std::size_t(W));
  ASSERT_EQ(b.merge_locations(Bytes(msg.whole().begin() + 5, msg.whole().end()), 3 * W),
            std::size_t(W));
  EXPECT_FALSE(a.untouched(3));
  EXPECT_EQ(a.rgb(), b.rgb());
  EXPECT_EQ(a.ids(), b.ids());
  EXPECT_EQ(a.ids()[a.index(2, 3)], 2u);
}

// The digest and the depth comparison read a row not touched yet as its background without
// filling it in: the same answers as on an eagerly cleared copy, the row still untouched after.
TEST(Framebuffer, DigestAndDepthMapReadUntouchedRowsAsBackground) {
  const int W = 7;
  Framebuffer fb(W, RowSet::interleaved(1, 2, 9), glm::vec3(0.2f, 0.5f, 1)); // rows 1, 3, 5, 7
  fb.ready_row(3);
  const std::uint8_t red[3] = {255, 0, 0};
  ASSERT_TRUE(fb.test_and_write(fb.index(4, 3), 0.25f, 3, red));
  Framebuffer eager = fb;
  eager.rgb(); // every row filled in
  ASSERT_FALSE(eager.untouched(5));
  const std::vector<float> map = depth_map(eager);
  EXPECT_EQ(image_sha256(fb), image_sha256(eager));
  EXPECT_TRUE(same_depth_map(fb, map));
  EXPECT_TRUE(fb.untouched(1));
  EXPECT_TRUE(fb.untouched(5));
  // A map that differs in an untouched row, or in the drawn pixel, is told apart.
  std::vector<float> other = map;
  other[std::size_t(2 * W + 1)] = 0.5f; // row 5 (local 2)
  EXPECT_FALSE(same_depth_map(fb, other));
  other = map;
  other[fb.index(4, 3)] = 1.0f;
  EXPECT_FALSE(same_depth_map(fb, other));
  EXPECT_NE(image_sha256(fb),
            image_sha256(Framebuffer(W, RowSet::interleaved(1, 2, 9), glm::vec3(0.2f, 0.5f, 1))));
}
