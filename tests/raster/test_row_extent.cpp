// row_extent, the rows a triangle can touch from its projected vertices alone, against set-up:
// the same rows as the screen triangle set-up emits when the triangle needs no clipping, the whole
// screen when it is cut, none when it lies outside a plane.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

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

// What set-up says of the triangle v against row_extent's answer (any, y0, y1): the same rows when
// it needs no clipping, the whole screen when it is cut, nothing when row_extent says none.
enum class Kind { Inside, Cut, Outside };
Kind check_against_setup(const ProjectedVertex* const v[3], int W, int H, bool any, int y0, int y1,
                         int n) {
  TriangleBatch out;
  Counters cnt;
  setup_triangle({{v[0], v[1], v[2]}, {nullptr, nullptr, nullptr}, 0, 0}, W, H, false, out, cnt);
  if (cnt.triangles_clipped > 0) {
    if (!any)
      EXPECT_TRUE(out.tris.empty()) << n;
    else
      EXPECT_TRUE(y0 == 0 && y1 == H - 1) << n;
    return Kind::Cut;
  }
  if (!any) {
    EXPECT_TRUE(out.tris.empty()) << n;
    return Kind::Outside;
  }
  for (const ScreenTriangle& t : out.tris) { // none when culled for a zero area
    EXPECT_EQ(t.ymin, y0) << n;
    EXPECT_EQ(t.ymax, y1) << n;
  }
  return Kind::Inside;
}

// How many triangles of each kind a test saw: each kind must be well represented, or the test
// would not test it.
struct Tally {
  int count[3] = {};
  void add(Kind k) { ++count[int(k)]; }
  void expect_at_least(int inside, int cut, int outside) const {
    EXPECT_GT(count[int(Kind::Inside)], inside);
    EXPECT_GT(count[int(Kind::Cut)], cut);
    EXPECT_GT(count[int(Kind::Outside)], outside);
  }
};

} // namespace

TEST(RowExtent, MatchesSetUpInsideWholeScreenWhenCutNoneOutside) {
  std::mt19937 rng(12345);
  const int W = 97, H = 61;
  Tally tally;
  for (int n = 0; n < 20000; ++n) {
    // Small spreads keep most triangles inside; large ones cross the near, far and guard planes.
    const float spread = n % 4 == 0 ? 8.0f : 0.9f;
    const ProjectedVertex a = vertex(rng, spread), b = vertex(rng, spread), c = vertex(rng, spread);
    const ProjectedVertex* const v[3] = {&a, &b, &c};
    int y0 = -7, y1 = -7;
    const bool any = row_extent(v, W, H, y0, y1);
    tally.add(check_against_setup(v, W, H, any, y0, y1, n));
  }
  tally.expect_at_least(5000, 500, 100);
}

// A mesh's vertices shared by many triangles, each vertex's extent worked out once (as Blazek's
// nodes do): the same answers, also for vertices on a plane, behind the eye, at w = 0 and NaN.
TEST(RowExtent, FromSharedVertexExtentsMatchesSetUp) {
  std::mt19937 rng(777);
  const int W = 64, H = 45;
  std::vector<ProjectedVertex> pool;
  for (int i = 0; i < 300; ++i)
    pool.push_back(vertex(rng, i % 3 == 0 ? 6.0f : 0.95f));
  ProjectedVertex on_plane{}, behind{}, at_zero{}, nan{};
  on_plane.clip[3] = 1.0f;
  on_plane.clip[0] = float(kGuardBand);
  behind.clip[3] = -0.5f;
  nan.clip[0] = nan.clip[1] = nan.clip[2] = nan.clip[3] = std::nanf("");
  pool.insert(pool.end(), {on_plane, behind, at_zero, nan});
  std::vector<VertexExtent> ext;
  for (const ProjectedVertex& p : pool)
    ext.push_back(vertex_extent(p, H));
  std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
  Tally tally;
  for (int n = 0; n < 20000; ++n) {
    // Every fourth triangle takes a corner among the special vertices.
    const std::size_t i = n % 4 == 0 ? pool.size() - 1 - std::size_t(n / 4 % 4) : pick(rng);
    const std::size_t j = pick(rng), k = pick(rng);
    const ProjectedVertex* const v[3] = {&pool[i], &pool[j], &pool[k]};
    const VertexExtent* const e[3] = {&ext[i], &ext[j], &ext[k]};
    int y0 = -7, y1 = -7;
    const bool any = row_extent(v, e, H, y0, y1);
    tally.add(check_against_setup(v, W, H, any, y0, y1, n));
  }
  tally.expect_at_least(3000, 500, 100);
}
