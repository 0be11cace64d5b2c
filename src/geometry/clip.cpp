#include "geometry/clip.hpp"

namespace zc {
namespace {

// Signed distance to plane k (>= 0 inside). Planes: near z>=-w, far z<=w, then the guard band.
inline double plane_dist(const ClipVertex& p, int k, double g) {
  const double x = p.a[0], y = p.a[1], z = p.a[2], w = p.a[3];
  switch (k) {
  case 0:
    return z + w;
  case 1:
    return w - z;
  case 2:
    return g * w + x;
  case 3:
    return g * w - x;
  case 4:
    return g * w + y;
  default:
    return g * w - y;
  }
}

ClipVertex intersect(const ClipVertex& in, double din, const ClipVertex& out, double dout, int k,
                     double g) {
  const double t = din / (din - dout);
  ClipVertex r;
  for (int i = 0; i < kClipAttrs; ++i)
    r.a[i] = in.a[i] + t * (out.a[i] - in.a[i]);
  // The new vertex lies on plane k by construction: state that exactly. With end points at 1e30
  // the interpolated coordinate is off by ~1e14, which would drag an edge far away from the
  // screen right across it; the snapped one is exact.
  const double w = r.a[3];
  switch (k) {
  case 0:
    r.a[2] = -w;
    break;
  case 1:
    r.a[2] = w;
    break;
  case 2:
    r.a[0] = -g * w;
    break;
  case 3:
    r.a[0] = g * w;
    break;
  case 4:
    r.a[1] = -g * w;
    break;
  default:
    r.a[1] = g * w;
    break;
  }
  return r;
}

} // namespace

ClipResult clip_polygon(ClipPolygon& poly, double guard) {
  // Outcodes first: most triangles need no clipping at all.
  unsigned all_and = 0x3f, any_or = 0;
  for (int i = 0; i < poly.n; ++i) {
    unsigned code = 0;
    for (int k = 0; k < 6; ++k)
      if (!(plane_dist(poly.v[i], k, guard) >= 0)) code |= 1u << k; // NaN counts as outside
    all_and &= code;
    any_or |= code;
  }
  if (all_and) return kClipOutside;
  if (!any_or) return kClipInside;

  for (int k = 0; k < 6; ++k) {
    if (!(any_or & (1u << k))) continue;
    ClipPolygon out;
    for (int i = 0; i < poly.n; ++i) {
      const ClipVertex& a = poly.v[i];
      const ClipVertex& b = poly.v[(i + 1) % poly.n];
      const double da = plane_dist(a, k, guard), db = plane_dist(b, k, guard);
      const bool ain = da >= 0, bin = db >= 0;
      if (ain) out.v[out.n++] = a;
      if (ain != bin) {
        if (out.n >= kClipMaxVerts) return kClipOutside; // cannot happen for convex input
        out.v[out.n++] =
            ain ? intersect(a, da, b, db, k, guard) : intersect(b, db, a, da, k, guard);
      }
    }
    poly = out;
    if (poly.n < 3) return kClipOutside;
  }
  return kClipCut;
}

} // namespace zc
