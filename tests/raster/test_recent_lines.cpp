// The far lines of the frame-buffer z-buffer (raster/recent_lines.hpp): counts against their
// closed forms.
#include <gtest/gtest.h>

#include "raster/recent_lines.hpp"
#include "raster/zbuffer.hpp"
#include "raster_fixtures.hpp"

using namespace zc;
using namespace zc::test;

TEST(RecentLines, ClearEntersEveryLineInOrder) {
  // 20,000 lines: after the clear, slot j holds the last line j + 8,192 k below 20,000.
  RecentLines r;
  r.reset(16 * 20000);
  EXPECT_EQ(r.enter(0, 0), 1u);                       // line 0: its slot holds 16,384
  EXPECT_EQ(r.enter(0, 15), 0u);                      // line 0 again
  EXPECT_EQ(r.enter(16 * 19999, 16 * 19999 + 5), 0u); // the clear's last line (slot 3,615)
  EXPECT_EQ(r.enter(16 * 13192, 16 * 13192), 0u);     // 5,000 + 8,192: slot 5,000's last line
  EXPECT_EQ(r.enter(16 * 11807, 16 * 11807), 1u);     // 3,615 + 8,192 evicts 19,999 ...
  EXPECT_EQ(r.enter(16 * 19999, 16 * 19999), 1u);     // ... which evicts it in turn
  EXPECT_EQ(r.enter(0, 16 * 3 - 1), 2u);              // lines 0 (in), 1 and 2 (out)
  // A buffer of at most 8,192 lines is all in the window after its clear.
  RecentLines small;
  small.reset(16 * 8192);
  EXPECT_EQ(small.enter(0, 16 * 8192 - 1), 0u);
  small.reset(100); // 7 lines, the last one partial
  EXPECT_EQ(small.enter(0, 99), 0u);
}

TEST(RecentLines, DrawBatchCountsTheSpansLinesOutsideTheWindow) {
  // The right triangle of HandCountedRightTriangle (rows 0-6, columns 0 to 6 - y) in a frame
  // buffer of 1,024 x 256: 16,384 lines of 16 locations, each row 64 of them. After the clear the
  // window holds lines 8,192-16,383, so each span enters one far line (row y's first, 64 y); the
  // same triangle drawn again enters none.
  const int w = 1024, h = 256;
  TriangleBatch b = right_triangle(w, h);
  ASSERT_EQ(b.tris.size(), 1u);
  Framebuffer fb(w, RowSet::all(h), glm::vec3(0));
  ShadeContext ctx;
  std::vector<Material> mats{Material{}};
  ctx.materials = &mats;
  Counters c;
  draw_batch(b, ctx, fb, c);
  EXPECT_EQ(c.spans, 7u);
  EXPECT_EQ(c.far_lines, 7u);
  draw_batch(b, ctx, fb, c);
  EXPECT_EQ(c.far_lines, 7u);
  // After a clear the window is the clear's again.
  fb.clear(glm::vec3(0));
  draw_batch(b, ctx, fb, c);
  EXPECT_EQ(c.far_lines, 14u);
  // A buffer within the window (1,024 x 8: 512 lines) has no far line.
  Framebuffer small(w, RowSet::band(0, 8), glm::vec3(0));
  Counters s;
  draw_batch(b, ctx, small, s);
  EXPECT_EQ(s.far_lines, 0u);
}
