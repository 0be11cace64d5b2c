// geometry/clip: homogeneous clipping against the near and far planes and the guard band, on the
// stiff cases (near-plane crossings, vertices behind the eye and at 1e30, NaN), and the
// determinism shared edges rely on.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "geometry/clip.hpp"

using namespace zc;

namespace {

constexpr double kGuard = 2.0;

ClipVertex vertex(double x, double y, double z, double w, double r = 0) {
  ClipVertex v{};
  v.a[0] = x;
  v.a[1] = y;
  v.a[2] = z;
  v.a[3] = w;
  v.a[4] = r;
  return v;
}

ClipPolygon triangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c) {
  ClipPolygon p;
  p.v[0] = a;
  p.v[1] = b;
  p.v[2] = c;
  p.n = 3;
  return p;
}

// Every vertex inside the view volume (near, far and the guard band), within `tol` of w.
void expect_inside(const ClipPolygon& p, double tol = 0) {
  for (int i = 0; i < p.n; ++i) {
    const auto& a = p.v[std::size_t(i)].a;
    const double w = a[3];
    EXPECT_GE(a[2], -w - tol) << "near, vertex " << i;
    EXPECT_LE(a[2], w + tol) << "far, vertex " << i;
    EXPECT_LE(std::abs(a[0]), kGuard * w + tol) << "x guard, vertex " << i;
    EXPECT_LE(std::abs(a[1]), kGuard * w + tol) << "y guard, vertex " << i;
  }
}

} // namespace

TEST(Clip, InsideAndOutsideAreLeftAlone) {
  ClipPolygon in = triangle(vertex(0, 0, 0, 1), vertex(0.5, 0, 0.2, 1), vertex(0, 0.5, -0.2, 1));
  EXPECT_EQ(clip_polygon(in, kGuard), kClipInside);
  EXPECT_EQ(in.n, 3);
  ClipPolygon beyond_far =
      triangle(vertex(0, 0, 2, 1), vertex(0.5, 0, 3, 1), vertex(0, 0.5, 2.5, 1));
  EXPECT_EQ(clip_polygon(beyond_far, kGuard), kClipOutside);
}

TEST(Clip, ANearPlaneCrossingIsCutOnThePlaneAndInterpolatesItsAttributes) {
  // One vertex behind the near plane (z < -w): the cut gives a quadrilateral.
  ClipPolygon p =
      triangle(vertex(0, 0, -3, 1, 1.0), vertex(0.5, 0, 0, 1, 0.0), vertex(0, 0.5, 0, 1, 0.0));
  ASSERT_EQ(clip_polygon(p, kGuard), kClipCut);
  ASSERT_EQ(p.n, 4);
  expect_inside(p);
  int on_near = 0;
  for (int i = 0; i < p.n; ++i) {
    const auto& a = p.v[std::size_t(i)].a;
    if (a[2] == -a[3]) {
      ++on_near;
      // From z = -3 (r = 1) to z = 0 (r = 0) the plane z = -1 is a third of the way back.
      EXPECT_NEAR(a[4], 1.0 / 3.0, 1e-15);
    }
  }
  EXPECT_EQ(on_near, 2) << "the two new vertices lie exactly on the near plane";
}

TEST(Clip, VerticesBehindTheEyeAndFarAwayStayInTheGuardBand) {
  // w < 0 (behind the eye) and a vertex at 1e30: the cut vertices are exact on their planes and
  // small enough for fixed-point rasterisation.
  ClipPolygon p =
      triangle(vertex(0.1, 0.1, 0.5, 1), vertex(1e30, 0.2, 0.5, 1), vertex(0.3, -0.4, 2, -1));
  ASSERT_EQ(clip_polygon(p, kGuard), kClipCut);
  ASSERT_GE(p.n, 3);
  expect_inside(p, 1e-12);
  for (int i = 0; i < p.n; ++i)
    EXPECT_GT(p.v[std::size_t(i)].a[3], 0) << "every vertex left in front of the eye";
}

TEST(Clip, NaNIsOutside) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ClipPolygon p = triangle(vertex(nan, nan, nan, nan), vertex(nan, 0, 0, 1), vertex(0, nan, 0, 1));
  EXPECT_EQ(clip_polygon(p, kGuard), kClipOutside);
}

TEST(Clip, ASharedEdgeIsCutIdenticallyFromBothTriangles) {
  // Two triangles share the edge a-b, which crosses the near plane; listed in opposite directions
  // the edge must give bit-identical cut vertices (no crack, no double-drawn pixel).
  const ClipVertex a = vertex(-0.3, 0.1, -2.7, 1.1), b = vertex(0.4, -0.2, 0.3, 0.9);
  ClipPolygon left = triangle(a, b, vertex(-0.5, 0.6, 0.1, 1));
  ClipPolygon right = triangle(b, a, vertex(0.6, 0.5, 0.2, 1));
  ASSERT_EQ(clip_polygon(left, kGuard), kClipCut);
  ASSERT_EQ(clip_polygon(right, kGuard), kClipCut);
  const auto on_near = [](const ClipPolygon& p) {
    for (int i = 0; i < p.n; ++i)
      if (p.v[std::size_t(i)].a[2] == -p.v[std::size_t(i)].a[3] &&
          p.v[std::size_t(i)].a[0] > -0.29 && p.v[std::size_t(i)].a[0] < 0.39)
        return p.v[std::size_t(i)];
    ADD_FAILURE() << "no cut vertex on the shared edge";
    return ClipVertex{};
  };
  const ClipVertex l = on_near(left), r = on_near(right);
  for (int i = 0; i < kClipAttrs; ++i)
    EXPECT_EQ(l.a[std::size_t(i)], r.a[std::size_t(i)]) << "attribute " << i;
}
