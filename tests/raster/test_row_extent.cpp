// row_extent, the rows a triangle can touch from its projected vertices alone, against set-up:
// the same rows as the screen triangle set-up emits when the triangle needs no clipping, the whole
// screen when it is cut, none when it lies outside a plane.
#include <gtest/gtest.h>

#include <random>

#include "raster/setup.hpp"

using namespace zc;

namespace {

ProjectedVertex vertex(std::mt19937& rng, float spread) {
  std::uniform_real_distribution<float> u(-spread, spread), w(0.2f, 3.0f);
  ProjectedVertex p{};
  p.clip[3] = w(rng);
  for (int k = 0; k < 3; ++k)
    p.clip[k] = u(rng) * p.clip[3];
  return p;
}

} // namespace

TEST(RowExtent, MatchesSetUpInsideWholeScreenWhenCutNoneOutside) {
  std::mt19937 rng(12345);
  const int W = 97, H = 61;
  int inside = 0, cut = 0, outside = 0;
  for (int n = 0; n < 20000; ++n) {
    // Small spreads keep most triangles inside; large ones cross the near, far and guard planes.
    const float spread = n % 4 == 0 ? 8.0f : 0.9f;
    const ProjectedVertex a = vertex(rng, spread), b = vertex(rng, spread), c = vertex(rng, spread);
    const ProjectedVertex* const v[3] = {&a, &b, &c};
    int y0 = -7, y1 = -7;
    const bool any = row_extent(v, W, H, y0, y1);
    TriangleBatch out;
    Counters cnt;
    setup_triangle({{&a, &b, &c}, {nullptr, nullptr, nullptr}, 0, 0}, W, H, false, out, cnt);
    if (cnt.triangles_clipped > 0) {
      ++cut;
      if (!any)
        EXPECT_TRUE(out.tris.empty()) << n;
      else
        EXPECT_TRUE(y0 == 0 && y1 == H - 1) << n;
      continue;
    }
    if (!any) {
      ++outside;
      EXPECT_TRUE(out.tris.empty()) << n;
      continue;
    }
    ++inside;
    for (const ScreenTriangle& t : out.tris) { // none when culled for a zero area
      EXPECT_EQ(t.ymin, y0) << n;
      EXPECT_EQ(t.ymax, y1) << n;
    }
  }
  EXPECT_GT(inside, 5000);
  EXPECT_GT(cut, 500);
  EXPECT_GT(outside, 100);
}
