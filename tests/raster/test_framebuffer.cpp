// Framebuffer edge cases found by the hostile review.
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
