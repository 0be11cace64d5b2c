// Kurc, Aykanat, Ozguc: full z-buffer merging (ZBUF-EXC), the paper's baseline. Each node
// z-buffers its spans into a full-screen frame buffer (below: each span of the lists started from
// its planes and drawn by the frame-buffer z-buffer's pixel loop, raster/zbuffer.hpp); the merge
// is binary swap of that dense picture over the even halving of the screen
// (compositing/binary_swap.cpp): stage i halves the current band and swaps halves with the
// neighbour over channel i, every location compared.
#include "algo/kurc/kurc_merge_scheme.hpp"
#include "algo/records.hpp"
#include "raster/recent_records.hpp"
#include "raster/zbuffer.hpp"

namespace zc::kurc {

Framebuffer full_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans,
                         Counters& w) {
  Framebuffer full = nr.make_framebuffer(RowSet::all(nr.height()));
  ctx.alloc(double(full.pixel_count() * records::kurc::kZbufferLocation), "full z-buffer");
  w.pixels_cleared = std::uint64_t(nr.width()) * nr.height();
  RecentRecords records; // the set-up records read last (a fetch from memory on a host)
  records.reset(spans.batch.tris.size());
  for (int y = 0; y < nr.height(); ++y)
    for (std::uint32_t s = spans.lists.row_begin[y]; s < spans.lists.row_begin[y + 1]; ++s) {
      const SpanRecord& sp = spans.lists.spans[s];
      w.records_fetched += records.read(sp.tri);
      draw_span(spans.batch.tris[sp.tri], spans.batch, nr.shade(), y, sp.x0, sp.x1, full, w);
    }
  return full;
}

} // namespace zc::kurc
