#pragma once
// The numeric range the renderer handles exactly (docs: scenes/README.md, "Numeric range").
//
// Vertices are projected in double precision but stored as float clip-space coordinates
// (raster/view.hpp), which then snap to the fixed-point screen grid (raster/setup.cpp; exact inside
// the guard band). Within this range every clip-space value stays a finite float with a margin, so
// a scene and its camera scaled by a power of two render the same bits. Outside it (an eye at
// 1e308, vertices near FLT_MAX, a 1e-37 degree field of view) clip-space values overflow and
// triangles are lost, so such scenes are refused on loading instead of rendering blank.
//   |coordinate| <= 2^64 (1.8e19): every vertex after its object transform, camera eye, target,
//     up, near and far; so |vertex - eye| < 2^66.
//   extents >= 2^-64 (5.4e-20): the distance from eye to target, the length of up and, when it is
//     not a single point, the scene's bounding radius (the near/far fit divides by it).
//   field of view >= 1e-9 degrees: 1 / tan(fov / 2) <= 2^37, times the widest aspect (2^14, a
//     1x16384 image) and 2^66 stays below 2^117, far from FLT_MAX (2^128).
#include "scene/scene.hpp"

namespace zc {

constexpr double kMaxCoordinate = 0x1p64;
constexpr double kMinExtent = 0x1p-64;
constexpr double kMinFovDeg = 1e-9;

// Throws InputError naming the scene file and the field (camera.eye, camera.fov, a vertex of an
// object) outside the range above.
void check_numeric_range(const Scene& scene);

} // namespace zc
