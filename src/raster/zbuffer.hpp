#pragma once
// The scanline z-buffer (Charles et al. §2): every screen triangle is scanned row by row over the
// rows of the frame buffer, and each generated pixel is kept if it is in front of the stored one.
#include "raster/framebuffer.hpp"
#include "raster/setup.hpp"
#include "raster/shade.hpp"
#include "util/counters.hpp"

namespace zc {

// Calls f(y, x0, x1) for every non-empty span of `t` on the rows of `rows`.
template <class F>
void for_each_span(const ScreenTriangle& t, const RowSet& rows, int width, F&& f) {
  int y = rows.first_from(t.ymin);
  const int yend = std::min(t.ymax + 1, rows.end);
  for (; y < yend; y += rows.stride) {
    int x0, x1;
    if (t.span(y, width, x0, x1)) f(y, x0, x1);
  }
}

// Scan-converts one screen triangle into `fb`, on the rows of `rows` (a subset of fb.rows()).
// When `newly_covered` is given, it is increased by the pixels this triangle writes first (pixels
// that held no triangle before): summed over a frame, the covered pixels without a final scan.
void draw_triangle(const ScreenTriangle& t, const TriangleBatch& batch, const ShadeContext& ctx,
                   const RowSet& rows, Framebuffer& fb, Counters& c,
                   std::uint64_t* newly_covered = nullptr);

// Draws every triangle of a batch, in order.
void draw_batch(const TriangleBatch& batch, const ShadeContext& ctx, Framebuffer& fb, Counters& c);

} // namespace zc
