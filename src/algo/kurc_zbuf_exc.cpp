// Kurc, Aykanat, Ozguc: full z-buffer merging (ZBUF-EXC), the paper's baseline. Each node
// z-buffers its spans into a full-screen frame buffer (below); the merge is binary swap of that
// dense picture over the even halving of the screen (compositing/binary_swap.cpp): stage i halves
// the current band and swaps halves with the neighbour over channel i, every location compared.
#include "algo/kurc_merge_scheme.hpp"
#include "algo/records.hpp"
#include "raster/zbuffer.hpp"

namespace zc::kurc {

namespace {

// One span of the span lists z-buffered into the full frame buffer.
void draw_span(Framebuffer& full, const NodeRenderer& nr, const NodeSpans& spans,
               const SpanRecord& sp, int y, Counters& w) {
  const ScreenTriangle& t = spans.batch.tris[sp.tri];
  const RowShader rs(t, spans.batch, nr.shade(), y);
  ++w.span_starts;
  for (int x = sp.x0; x <= sp.x1; ++x) {
    const std::size_t i = full.index(x, y);
    const float z = rs.depth(x);
    if (!in_front(z, t.id, full.depth()[i], full.ids()[i])) continue;
    std::uint8_t rgb[3];
    rs.color(x, rgb, w);
    full.test_and_write(i, z, t.id, rgb);
    ++w.pixels_written;
  }
  w.pixels_generated += std::uint64_t(sp.x1 - sp.x0 + 1);
  w.pixels_tested += std::uint64_t(sp.x1 - sp.x0 + 1);
}

} // namespace

Framebuffer full_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans,
                         Counters& w) {
  Framebuffer full = nr.make_framebuffer(RowSet::all(nr.height()));
  ctx.alloc(double(full.pixel_count() * records::kurc::kZbufferLocation), "full z-buffer");
  w.pixels_cleared = std::uint64_t(nr.width()) * nr.height();
  for (int y = 0; y < nr.height(); ++y)
    for (std::uint32_t s = spans.lists.row_begin[y]; s < spans.lists.row_begin[y + 1]; ++s)
      draw_span(full, nr, spans, spans.lists.spans[s], y, w);
  return full;
}

} // namespace zc::kurc
