#pragma once
// Homogeneous clipping of a convex polygon against the view volume (Sutherland-Hodgman) in double
// precision. Near and far planes are exact; left/right/top/bottom are a guard band `guard` times
// the viewport, so screen coordinates stay small enough for exact fixed-point rasterisation even
// for vertices at 1e30 or behind the eye, while triangles that merely overhang the screen edge are
// not cut (the rasteriser's scissor handles them).
//
// Determinism: the intersection of an edge with a plane is always computed from its inside end
// towards its outside end, so two triangles sharing an edge get bit-identical clipped vertices.
#include <array>
#include <cstddef>

namespace zc {

constexpr int kClipAttrs = 9;    // x y z w | r g b | u v
constexpr int kClipMaxVerts = 9; // a triangle cut by 6 planes has at most 9 vertices

struct ClipVertex {
  std::array<double, kClipAttrs> a; // a[0..3] = clip position, the rest interpolated linearly
};

struct ClipPolygon {
  std::array<ClipVertex, kClipMaxVerts> v;
  int n = 0;
};

enum ClipResult { kClipInside, kClipOutside, kClipCut };

// Clips `poly` in place. Returns whether it was entirely inside, entirely outside, or cut.
ClipResult clip_polygon(ClipPolygon& poly, double guard);

} // namespace zc
