#pragma once
// Triangle set-up: clip in homogeneous space, snap to a fixed-point grid (8 sub-pixel bits), and
// derive the exact integer edge functions (with the top-left fill rule) and the attribute planes.
// A screen triangle is a pure function of its three projected vertices, so every node that sets up
// the same triangle gets the same bits, whatever else it renders. Scenes are held on loading to
// the coordinate range that keeps every clip-space value a finite float (scene/scene_range.hpp,
// scenes/README.md 'Numeric range'); a vertex beyond it that still arrives is dropped here.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "raster/view.hpp"
#include "util/counters.hpp"

namespace zc {

constexpr int kSubBits = 8;
constexpr std::int64_t kSub = 1 << kSubBits; // fixed-point units per pixel
constexpr double kGuardBand = 4.0;           // clip x, y at 4x the viewport (see geometry/clip)

// A plane over integer pixel indices (pixel centres already folded into a0). It is always
// evaluated as (a0 + ay*y) + ax*x, row base first, so a value never depends on who evaluates it.
struct AttrPlane {
  double a0 = 0, ax = 0, ay = 0;
  double row(int y) const { return a0 + ay * y; }
  double at(int x, int y) const { return row(y) + ax * x; }
};

// Perspective-correct texture planes: u/w, v/w and 1/w are affine in screen space.
struct TexPlanes {
  AttrPlane uw, vw, w1;
};

struct ScreenTriangle {
  std::uint32_t id = 0; // global triangle id: the depth tie-break (lower wins)
  std::uint32_t material = 0;
  std::int32_t tex = -1;   // index into TriangleBatch::tex, -1 when untextured
  int ymin = 0, ymax = -1; // rows whose centre lies inside the vertical extent, clamped
  // Columns whose centre lies inside the horizontal extent, clamped to the screen; bx1 < bx0 when
  // not known (a screen wider than 32767 pixels). In what was padding: the size is unchanged.
  std::int16_t bx0 = 0, bx1 = -1;
  // Edge i: inside iff A*px + B*py + C - bias >= 0 at the fixed-point pixel centre (px, py).
  std::int64_t A[3], B[3], C[3];
  std::int64_t bias[3]; // 0 on top/left edges, 1 elsewhere (the top-left rule)
  AttrPlane z;          // window depth in [0, 1]
  AttrPlane r, g, b;    // Gouraud light (material colour applied per fragment)

  // Inclusive span of pixel columns of row y inside the triangle, clamped to [0, width).
  // Returns false when the row holds no pixel of the triangle.
  bool span(int y, int width, int& x0, int& x1) const;
};

static_assert(sizeof(ScreenTriangle) == 216); // the simulated nodes' set-up records

struct TriangleBatch {
  std::vector<ScreenTriangle> tris;
  std::vector<TexPlanes> tex; // only filled for textured triangles
  void clear() {
    tris.clear();
    tex.clear();
  }
};

struct SetupInput {
  const ProjectedVertex* v[3];
  const glm::vec2* uv[3]; // all null for an untextured triangle
  std::uint32_t id;
  std::uint32_t material;
};

// Rows [y0, y1] (inclusive) a triangle can touch, from its projected vertices alone: exactly the
// rows set-up would give when the triangle needs no clipping (same snapping), the whole screen
// when it does (clipping only shrinks). Returns false when it certainly touches no row.
bool row_extent(const ProjectedVertex* const v[3], int width, int height, int& y0, int& y1);

// What row_extent needs of one projected vertex: its clip outcode and, when it lies inside every
// plane, its snapped y. A mesh whose triangles share vertices (about six a vertex) works it out
// once a vertex instead of once a corner.
struct VertexExtent {
  std::int64_t y = 0; // snapped y, fixed point (code 0 only)
  unsigned code = 0;  // the planes it lies outside (NaN: outside)
};
VertexExtent vertex_extent(const ProjectedVertex& v, int height);
// row_extent from the corners' extents, e[k] = vertex_extent(*v[k], height): the same answer.
bool row_extent(const ProjectedVertex* const v[3], const VertexExtent* const e[3], int height,
                int& y0, int& y1);

// Appends the screen triangles of one scene triangle (0 if culled or off-screen, several if
// clipped).
void setup_triangle(const SetupInput& in, int width, int height, bool cull_back, TriangleBatch& out,
                    Counters& counters);

} // namespace zc
