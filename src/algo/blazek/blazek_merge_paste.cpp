// Blazek 1991, ch. V: the hierarchical frame buffer merge (Algorithm 4, Figure 10) and the
// pasting of partial images at node 0 (blazek_merge_paste.hpp).
#include "algo/blazek/blazek_merge_paste.hpp"

#include "algo/blazek/blazek_common.hpp"
#include "algo/blazek/blazek_wire.hpp"
#include "algo/composite.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "compositing/dense.hpp"
#include "compositing/gather.hpp"

namespace zc::blazek {

// Tree compositing of the dense frame buffers (compositing/tree.cpp), each location charged as
// the thesis's frame-buffer pixel; every location is compared (Algorithm 4), straight out of the
// received buffer, and charged before the node sends its merged buffer on.
void hierarchical_merge(NodeContext& ctx, Framebuffer fb) {
  auto ph = ctx.phase("merge");
  compositing::PixelRecords rec;
  rec.location = records::blazek::kFrameBufferPixel;
  const int height = fb.rows().end;
  auto picture = compositing::dense(std::move(fb), rec);
  Counters w;
  composite(ctx, compositing::tree(), *picture, std::vector<int>(std::size_t(height), 0), w,
            MergeCharge::ByRound);
  if (ctx.rank() == 0) ctx.deliver_image(0, std::move(compositing::framebuffer(*picture)));
}

void paste_at_node0(NodeContext& ctx, const Framebuffer& part) {
  auto ph = ctx.phase("paste");
  // The node's rows (a strip or interleaved) are one contiguous array of its frame buffer, sent
  // in place to node 0, which displays them: no packing is charged. Only colour travels (ch. V);
  // the picture and its depth map are the rows each node rendered, handed over once sent (the
  // colour node 0 receives is these rows' colour, byte for byte).
  (void)compositing::gather(ctx.comm(), 0,
                            charged_as_payload(Bytes(part.rgb().begin(), part.rgb().end())));
  (void)coll::gatherv(
      ctx.comm(), 0,
      pack(std::vector<int>{part.rows().begin, part.rows().end, part.rows().stride}));
  ctx.deliver_rows(0, part);
}

} // namespace zc::blazek
