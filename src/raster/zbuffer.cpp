#include "raster/zbuffer.hpp"

namespace zc {

namespace {

// The span loop with every plane coefficient, frame-buffer pointer and counter in a local: the
// colour stores go through uint8_t pointers, which may alias anything, so values read through
// references would be reloaded after every pixel. Same arithmetic, same order, same bits as
// RowShader (depth, then (r0 + ax*x) * kd per channel).
void draw_untextured(const ScreenTriangle& t, const ShadeContext& ctx, const RowSet& rows,
                     Framebuffer& fb, Counters& c, std::uint64_t* newly_covered) {
  float* const depth = fb.depth().data();
  std::uint32_t* const ids = fb.ids().data();
  std::uint8_t* const rgb = fb.rgb().data();
  const glm::vec3 kd = (*ctx.materials)[t.material].kd;
  const std::uint32_t id = t.id;
  const double zax = t.z.ax, rax = t.r.ax, gax = t.g.ax, bax = t.b.ax;
  std::uint64_t spans = 0, generated = 0, written = 0, first = 0;
  for_each_span(t, rows, fb.width(), [&](int y, int x0, int x1) {
    ++spans;
    const double z0 = t.z.row(y), r0 = t.r.row(y), g0 = t.g.row(y), b0 = t.b.row(y);
    std::size_t i = fb.index(x0, y);
    for (int x = x0; x <= x1; ++x, ++i) {
      const float z = static_cast<float>(z0 + zax * x);
      if (!in_front(z, id, depth[i], ids[i])) continue;
      const float r = float(r0 + rax * x) * kd.x;
      const float g = float(g0 + gax * x) * kd.y;
      const float b = float(b0 + bax * x) * kd.z;
      first += ids[i] == kNoTriangle;
      depth[i] = z;
      ids[i] = id;
      rgb[3 * i] = unit_to_byte(r);
      rgb[3 * i + 1] = unit_to_byte(g);
      rgb[3 * i + 2] = unit_to_byte(b);
      ++written;
    }
    generated += std::uint64_t(x1 - x0 + 1);
  });
  c.spans += spans;
  c.pixels_generated += generated;
  c.pixels_tested += generated;
  c.pixels_written += written;
  if (newly_covered) *newly_covered += first;
}

} // namespace

void draw_triangle(const ScreenTriangle& t, const TriangleBatch& batch, const ShadeContext& ctx,
                   const RowSet& rows, Framebuffer& fb, Counters& c, std::uint64_t* newly_covered) {
  if (t.tex < 0) {
    draw_untextured(t, ctx, rows, fb, c, newly_covered);
    return;
  }
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
      if (newly_covered) *newly_covered += ids[i] == kNoTriangle;
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
