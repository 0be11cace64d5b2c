// The far lines of the frame-buffer z-buffer (raster/recent_lines.hpp): counts against their
// closed forms.
#include <gtest/gtest.h>

#include "raster/recent_lines.hpp"
#include "raster/zbuffer.hpp"
#include "raster_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {
// Draws the right triangle of HandCountedRightTriangle (rows 0-6, columns 0 to 6 - y), set up for
// fb's width and `h` rows, into fb, adding its counts to c.
void draw_right_triangle(Framebuffer& fb, int h, Counters& c) {
  const TriangleBatch b = right_triangle(fb.width(), h);
  ASSERT_EQ(b.tris.size(), 1u);
  ShadeContext ctx;
  std::vector<Material> mats{Material{}};
  ctx.materials = &mats;
  draw_batch(b, ctx, fb, c);
}
} // namespace

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
  Framebuffer fb(w, RowSet::all(h), glm::vec3(0));
  Counters c;
  draw_right_triangle(fb, h, c);
  EXPECT_EQ(c.spans, 7u);
  EXPECT_EQ(c.far_lines, 7u);
  draw_right_triangle(fb, h, c);
  EXPECT_EQ(c.far_lines, 7u);
  // After a clear the window is the clear's again.
  fb.clear(glm::vec3(0));
  draw_right_triangle(fb, h, c);
  EXPECT_EQ(c.far_lines, 14u);
  // A buffer within the window (1,024 x 8: 512 lines) has no far line.
  Framebuffer small(w, RowSet::band(0, 8), glm::vec3(0));
  Counters s;
  draw_right_triangle(small, h, s);
  EXPECT_EQ(s.far_lines, 0u);
}

TEST(RecentLines, DistantLinesAreFarLinesOutsideTheLastLevelWindow) {
  constexpr std::size_t W = RecentLines::kWindow, L = RecentLines::kLlcWindow;
  static_assert(L % W == 0 && L >= 2 * W, "the windows nest");
  // N = 3.75 L lines: after the clear, the window's slot j holds the last line j + W k below N,
  // the last-level window's slot j the last line j + L k.
  const std::size_t N = 3 * L + 3 * L / 4;
  RecentLines r;
  r.reset(16 * N);
  std::uint64_t distant = 0;
  EXPECT_EQ(r.enter(0, 0, &distant), 1u); // line 0: both its slots hold later lines
  EXPECT_EQ(distant, 1u);
  // Line 3 L + 5 is the last of its last-level slot (3 L + 5 + L > N), not of its window slot
  // (3 L + 5 + W < N): far, but in the last-level window.
  EXPECT_EQ(r.enter(16 * (3 * L + 5), 16 * (3 * L + 5), &distant), 1u);
  EXPECT_EQ(distant, 1u);
  EXPECT_EQ(r.enter(0, 15, &distant), 0u); // line 0 again: near
  EXPECT_EQ(distant, 1u);
  // Line W evicts line 0 from the window, not from the last-level window: 0 is far again, not
  // distant.
  EXPECT_EQ(r.enter(16 * W, 16 * W, &distant), 1u);
  EXPECT_EQ(distant, 2u); // W itself: its last-level slot held 3 L + W
  EXPECT_EQ(r.enter(0, 0, &distant), 1u);
  EXPECT_EQ(distant, 2u);
  // A buffer of at most L lines has far lines but no distant one (entered in order, each line
  // evicts from the window the one its slot held before that one is entered: all far).
  RecentLines llc;
  llc.reset(16 * L);
  std::uint64_t none = 0;
  EXPECT_EQ(llc.enter(0, 16 * L - 1, &none), L);
  EXPECT_EQ(none, 0u);
}

TEST(RecentLines, DrawBatchCountsDistantLinesInAFrameBufferBeyondTheLastLevelWindow) {
  // The right triangle (rows 0-6) in 2,048 x 1,100: 140,800 lines, 128 a row, 8 L + 9,728. After
  // the clear the last-level window holds lines 8 L and above in the slots below 9,728: every
  // span's first line (128 y) is far and distant; drawn again, neither.
  static_assert(140800 % RecentLines::kLlcWindow == 9728);
  const int w = 2048, h = 1100;
  Framebuffer fb(w, RowSet::all(h), glm::vec3(0));
  Counters c;
  draw_right_triangle(fb, h, c);
  ASSERT_EQ(c.spans, 7u);
  EXPECT_EQ(c.far_lines, 7u);
  EXPECT_EQ(c.distant_lines, 7u);
  draw_right_triangle(fb, h, c);
  EXPECT_EQ(c.far_lines, 7u);
  EXPECT_EQ(c.distant_lines, 7u);
  // The 1,024 x 256 buffer of the test above (16,384 lines) fits the last-level window: far lines,
  // none distant.
  static_assert(1024 * 256 / 16 <= RecentLines::kLlcWindow);
  Framebuffer small(1024, RowSet::all(256), glm::vec3(0));
  Counters s;
  draw_right_triangle(small, 256, s);
  EXPECT_EQ(s.far_lines, 7u);
  EXPECT_EQ(s.distant_lines, 0u);
}
