#include "raster/zbuffer.hpp"

namespace zc {

void draw_triangle(const ScreenTriangle& t, const TriangleBatch& batch, const ShadeContext& ctx,
                   const RowSet& rows, Framebuffer& fb, Counters& c) {
  for_each_span(t, rows, fb.width(), [&](int y, int x0, int x1) {
    ++c.spans;
    const RowShader rs(t, batch, ctx, y);
    std::size_t i = fb.index(x0, y);
    auto& depth = fb.depth();
    auto& ids = fb.ids();
    for (int x = x0; x <= x1; ++x, ++i) {
      const float z = rs.depth(x);
      if (!in_front(z, t.id, depth[i], ids[i])) continue;
      std::uint8_t rgb[3];
      rs.color(x, rgb, c);
      fb.test_and_write(i, z, t.id, rgb);
      ++c.pixels_written;
    }
    const std::uint64_t n = std::uint64_t(x1 - x0 + 1);
    c.pixels_generated += n;
    c.pixels_tested += n;
  });
}

void draw_batch(const TriangleBatch& batch, const ShadeContext& ctx, Framebuffer& fb, Counters& c) {
  for (const auto& t : batch.tris)
    draw_triangle(t, batch, ctx, fb.rows(), fb, c);
}

} // namespace zc
