#include "raster/setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry/clip.hpp"

namespace zc {
namespace {

inline std::int64_t floor_div(std::int64_t a, std::int64_t b) { // b > 0
  std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}
inline std::int64_t ceil_div(std::int64_t a, std::int64_t b) {
  return -floor_div(-a, b);
} // b > 0

// floor(n / d) for d > 0, clamped to [lo, hi] (bounds of a few thousand), exactly as the integer
// division would give it but without a 64-bit divide: the double quotient is within 1 of the true
// one (|n| < 2^53 here, and beyond the bounds only its side matters), and integer products settle
// the last unit.
inline std::int64_t floor_div_clamped(std::int64_t n, std::int64_t d, std::int64_t lo,
                                      std::int64_t hi) {
  const double q = double(n) / double(d);
  if (!(q > double(lo - 2))) return lo;
  if (!(q < double(hi + 2))) return hi;
  std::int64_t f = std::int64_t(q);
  while (f * d > n)
    --f;
  while ((f + 1) * d <= n)
    ++f;
  return std::clamp(f, lo, hi);
}

// std::llround (half away from zero) without the library call, for |x| < 2^52 (x - trunc(x) is
// exact there); anything larger goes to std::llround.
inline std::int64_t round_half_away(double x) {
  if (!(std::fabs(x) < 4503599627370496.0)) return std::llround(x);
  const std::int64_t t = std::int64_t(x);
  const double r = x - double(t);
  return t + (r >= 0.5) - (r <= -0.5);
}

struct SnapVertex {
  std::int64_t X, Y; // fixed point
  double z;          // window depth
  double attr[5];    // r g b, and u v when textured
  double invw;
};

// The geometry every attribute plane of one triangle shares: the snapped vertices in pixel units,
// relative to the first, and twice the area.
struct PlaneFrame {
  double x0, y0, x1, y1, x2, y2, den;
  PlaneFrame(const SnapVertex* s, double den_)
      : x0(double(s[0].X) / kSub), y0(double(s[0].Y) / kSub), x1(double(s[1].X) / kSub - x0),
        y1(double(s[1].Y) / kSub - y0), x2(double(s[2].X) / kSub - x0),
        y2(double(s[2].Y) / kSub - y0), den(den_) {}

  // Plane through the three snapped vertices' values, in pixel units, evaluated at pixel centres.
  AttrPlane plane(double a0v, double a1v, double a2v) const {
    const double d1 = a1v - a0v, d2 = a2v - a0v;
    AttrPlane p;
    p.ax = (d1 * y2 - d2 * y1) / den;
    p.ay = (d2 * x1 - d1 * x2) / den;
    p.a0 = a0v - p.ax * x0 - p.ay * y0 + 0.5 * p.ax + 0.5 * p.ay;
    return p;
  }
};

void emit(const SnapVertex* s, const SetupInput& in, bool textured, int width, int height,
          TriangleBatch& out, Counters& c) {
  SnapVertex v[3] = {s[0], s[1], s[2]};
  std::int64_t area2 =
      (v[1].X - v[0].X) * (v[2].Y - v[0].Y) - (v[2].X - v[0].X) * (v[1].Y - v[0].Y);
  if (area2 == 0) {
    ++c.triangles_culled;
    return;
  }
  if (area2 < 0) {
    std::swap(v[1], v[2]);
    area2 = -area2;
  }
  ScreenTriangle t;
  t.id = in.id;
  t.material = in.material;
  const std::int64_t miny = std::min({v[0].Y, v[1].Y, v[2].Y});
  const std::int64_t maxy = std::max({v[0].Y, v[1].Y, v[2].Y});
  t.ymin = int(std::max<std::int64_t>(0, ceil_div(miny - kSub / 2, kSub)));
  t.ymax = int(std::min<std::int64_t>(height - 1, floor_div(maxy - kSub / 2, kSub)));
  const std::int64_t minx = std::min({v[0].X, v[1].X, v[2].X});
  const std::int64_t maxx = std::max({v[0].X, v[1].X, v[2].X});
  const std::int64_t bx0 = ceil_div(minx - kSub / 2, kSub);
  const std::int64_t bx1 = floor_div(maxx - kSub / 2, kSub);
  if (t.ymin > t.ymax || bx0 > width - 1 || bx1 < 0) {
    ++c.triangles_culled; // touches no pixel centre on screen
    return;
  }
  if (width <= 32767) {
    t.bx0 = std::int16_t(std::max<std::int64_t>(0, bx0));
    t.bx1 = std::int16_t(std::min<std::int64_t>(width - 1, bx1));
  }
  for (int e = 0; e < 3; ++e) {
    const SnapVertex& p = v[e];
    const SnapVertex& q = v[(e + 1) % 3];
    t.A[e] = p.Y - q.Y;
    t.B[e] = q.X - p.X;
    t.C[e] = p.X * q.Y - q.X * p.Y;
    const bool top_left = t.A[e] > 0 || (t.A[e] == 0 && t.B[e] > 0);
    t.bias[e] = top_left ? 0 : 1;
  }
  const PlaneFrame f(v, double(area2) / double(kSub * kSub));
  t.z = f.plane(v[0].z, v[1].z, v[2].z);
  t.r = f.plane(v[0].attr[0], v[1].attr[0], v[2].attr[0]);
  t.g = f.plane(v[0].attr[1], v[1].attr[1], v[2].attr[1]);
  t.b = f.plane(v[0].attr[2], v[1].attr[2], v[2].attr[2]);
  if (textured) {
    TexPlanes tp;
    tp.uw = f.plane(v[0].attr[3] * v[0].invw, v[1].attr[3] * v[1].invw, v[2].attr[3] * v[2].invw);
    tp.vw = f.plane(v[0].attr[4] * v[0].invw, v[1].attr[4] * v[1].invw, v[2].attr[4] * v[2].invw);
    tp.w1 = f.plane(v[0].invw, v[1].invw, v[2].invw);
    t.tex = std::int32_t(out.tex.size());
    out.tex.push_back(tp);
  }
  ++c.triangles_setup;
  out.tris.push_back(t);
}

// A clipped vertex lies within the guard band, so |X|, |Y| <= (2 kGuardBand + 1) * side * kSub <
// 2^27 and the edge products stay below 2^55: exact in 64 bits. A vertex outside it (or NaN) comes
// from clip-space values that overflowed; its triangle cannot be set up exactly and is dropped.
bool representable(const SnapVertex& s, int width, int height) {
  const double lim = (2 * kGuardBand + 2) * double(std::max(width, height)) * double(kSub);
  return std::fabs(double(s.X)) <= lim && std::fabs(double(s.Y)) <= lim && std::isfinite(s.z) &&
         std::isfinite(s.invw);
}

SnapVertex snap(const ClipVertex& cv, int width, int height) {
  const double invw = 1.0 / cv.a[3];
  const double sx = (cv.a[0] * invw * 0.5 + 0.5) * width;
  const double sy = (0.5 - cv.a[1] * invw * 0.5) * height;
  SnapVertex s;
  // NaN or beyond 2^62 (overflowed clip-space values): a sentinel representable() rejects.
  const double big = 4.0e18;
  s.X = std::fabs(sx * kSub) < big ? round_half_away(sx * kSub) : std::int64_t(big);
  s.Y = std::fabs(sy * kSub) < big ? round_half_away(sy * kSub) : std::int64_t(big);
  s.z = cv.a[2] * invw * 0.5 + 0.5;
  s.invw = invw;
  for (int i = 0; i < 5; ++i)
    s.attr[i] = cv.a[4 + i];
  return s;
}

// True when every vertex of the triangle `poly` is inside the six planes (clip_polygon's own
// distances, NaN outside): clip_polygon would return kClipInside and leave it as it is.
bool inside_view(const ClipPolygon& poly) {
  bool in = true;
  for (int i = 0; i < 3; ++i) {
    const double x = poly.v[i].a[0], y = poly.v[i].a[1], z = poly.v[i].a[2], w = poly.v[i].a[3];
    const double gw = kGuardBand * w;
    in &= z + w >= 0 && w - z >= 0 && gw + x >= 0 && gw - x >= 0 && gw + y >= 0 && gw - y >= 0;
  }
  return in;
}

// A projected vertex's clip outcode as clip_polygon works it out (the same planes and arithmetic on
// the same doubles; NaN counts as outside).
unsigned outcode(const ProjectedVertex& v) {
  const double x = v.clip[0], y = v.clip[1], z = v.clip[2], w = v.clip[3];
  const double gw = kGuardBand * w;
  return unsigned(!(z + w >= 0)) | unsigned(!(w - z >= 0)) << 1 | unsigned(!(gw + x >= 0)) << 2 |
         unsigned(!(gw - x >= 0)) << 3 | unsigned(!(gw + y >= 0)) << 4 |
         unsigned(!(gw - y >= 0)) << 5;
}

// snap(v).Y of a vertex inside every plane, without building its clip vertex.
std::int64_t snapped_y(const ProjectedVertex& v, int height) {
  const double invw = 1.0 / double(v.clip[3]);
  const double sy = (0.5 - double(v.clip[1]) * invw * 0.5) * height;
  const double big = 4.0e18;
  return std::fabs(sy * kSub) < big ? round_half_away(sy * kSub) : std::int64_t(big);
}

} // namespace

bool ScreenTriangle::span(int y, int width, int& x0, int& x1) const {
  const std::int64_t py = std::int64_t(y) * kSub + kSub / 2;
  std::int64_t lo = 0, hi = width - 1;
  for (int e = 0; e < 3; ++e) {
    const std::int64_t K = A[e] * (kSub / 2) + B[e] * py + C[e] - bias[e];
    // ceil(-K / D) = -floor(K / D); clamping to one past the screen keeps the outcome.
    if (A[e] > 0) {
      lo = std::max(lo, -floor_div_clamped(K, A[e] * kSub, -std::int64_t(width), 0));
    } else if (A[e] < 0) {
      hi = std::min(hi, floor_div_clamped(K, -A[e] * kSub, -1, std::int64_t(width) - 1));
    } else if (K < 0) {
      return false;
    }
  }
  if (lo > hi) return false;
  x0 = int(lo);
  x1 = int(hi);
  return true;
}

VertexExtent vertex_extent(const ProjectedVertex& v, int height) {
  VertexExtent e;
  e.code = outcode(v);
  if (e.code == 0) e.y = snapped_y(v, height);
  return e;
}

bool row_extent(const ProjectedVertex* const v[3], int width, int height, int& y0, int& y1) {
  (void)width; // the rows do not depend on it
  const VertexExtent e[3] = {vertex_extent(*v[0], height), vertex_extent(*v[1], height),
                             vertex_extent(*v[2], height)};
  const VertexExtent* const ep[3] = {&e[0], &e[1], &e[2]};
  return row_extent(v, ep, height, y0, y1);
}

bool row_extent(const ProjectedVertex* const v[3], const VertexExtent* const e[3], int height,
                int& y0, int& y1) {
  // Only the outcodes are needed from the clipper; most triangles lie inside every plane, and their
  // rows come from the vertices as set-up snaps them (no clip polygon built for them).
  const unsigned all_and = e[0]->code & e[1]->code & e[2]->code;
  const unsigned any_or = e[0]->code | e[1]->code | e[2]->code;
  if (all_and) return false;
  if (any_or) { // cut, or entirely outside once cut: clip_polygon tells which
    ClipPolygon poly;
    poly.n = 3;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < kClipAttrs; ++k)
        poly.v[i].a[k] = k < 4 ? double(v[i]->clip[k]) : 0.0;
    if (clip_polygon(poly, kGuardBand) == kClipOutside) return false;
    y0 = 0;
    y1 = height - 1;
    return height > 0;
  }
  const std::int64_t miny = std::min({e[0]->y, e[1]->y, e[2]->y});
  const std::int64_t maxy = std::max({e[0]->y, e[1]->y, e[2]->y});
  y0 = int(std::max<std::int64_t>(0, ceil_div(miny - kSub / 2, kSub)));
  y1 = int(std::min<std::int64_t>(height - 1, floor_div(maxy - kSub / 2, kSub)));
  return y0 <= y1;
}

void setup_triangle(const SetupInput& in, int width, int height, bool cull_back, TriangleBatch& out,
                    Counters& c) {
  ++c.triangles_in;
  const bool textured = in.uv[0] != nullptr;
  ClipPolygon poly;
  poly.n = 3;
  for (int i = 0; i < 3; ++i) {
    auto& a = poly.v[i].a;
    for (int k = 0; k < 4; ++k)
      a[k] = in.v[i]->clip[k];
    for (int k = 0; k < 3; ++k)
      a[4 + k] = in.v[i]->light[k];
    a[7] = textured ? in.uv[i]->x : 0.0;
    a[8] = textured ? in.uv[i]->y : 0.0;
  }
  // Most triangles lie inside every plane: clip_polygon's outcodes, without its general loop.
  const ClipResult cr = inside_view(poly) ? kClipInside : clip_polygon(poly, kGuardBand);
  if (cr == kClipOutside) {
    ++c.triangles_culled;
    return;
  }
  if (cr == kClipCut) ++c.triangles_clipped;

  SnapVertex s[kClipMaxVerts];
  for (int i = 0; i < poly.n; ++i) {
    s[i] = snap(poly.v[i], width, height);
    if (!representable(s[i], width, height)) {
      ++c.triangles_culled; // its clip-space numbers overflowed (coordinates near FLT_MAX)
      return;
    }
  }

  if (cull_back) {
    // Facing is decided on the whole (clipped) polygon: y points down on screen, so a
    // counter-clockwise (front-facing) polygon has a negative signed area here.
    std::int64_t area2 = 0;
    for (int i = 1; i + 1 < poly.n; ++i)
      area2 +=
          (s[i].X - s[0].X) * (s[i + 1].Y - s[0].Y) - (s[i + 1].X - s[0].X) * (s[i].Y - s[0].Y);
    if (area2 >= 0) {
      ++c.triangles_culled;
      return;
    }
  }
  for (int i = 1; i + 1 < poly.n; ++i) {
    const SnapVertex fan[3] = {s[0], s[i], s[i + 1]};
    emit(fan, in, textured, width, height, out, c);
  }
}

} // namespace zc
