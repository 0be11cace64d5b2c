// Blazek 1991, ch. V: the hierarchical frame buffer merge (Algorithm 4, Figure 10) and the
// pasting of partial images at node 0 (blazek_merge_paste.hpp).
#include "algo/blazek_merge_paste.hpp"

#include "algo/blazek_common.hpp"
#include "algo/blazek_wire.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"

namespace zc::blazek {

void hierarchical_merge(NodeContext& ctx, Framebuffer fb) {
  Comm& c = ctx.comm();
  const int r = c.rank();
  auto ph = ctx.phase("merge");
  for (int i = 0; (1 << i) < c.size(); ++i) {
    const int bit = 1 << i;
    if (r & (bit - 1)) break; // already sent its buffer
    if (r & bit) {
      // The frame buffer is sent in place (its arrays are contiguous): no packing is charged;
      // zcube's copy into one payload is an artefact of its wire format.
      // Charged as the thesis's frame buffer (records.hpp), without zcube's triangle ids.
      c.send(r ^ bit, kTagMerge,
             Message{fb.pack_locations(0, fb.pixel_count()), std::size_t(frame_buffer_bytes(fb))});
      return;
    }
    if ((r ^ bit) >= c.size()) continue; // no partner when P is not a power of two (a ring of 3)
    const Message got = c.recv_message(r ^ bit, kTagMerge);
    const Bytes& in = got.payload;
    ctx.alloc(double(got.charged), "merge receive buffer");
    Counters k;
    // Every location is compared (Algorithm 4), straight out of the received buffer.
    k.merge_ops = fb.merge_locations(in, 0);
    ctx.charge(k);
    ctx.release(double(got.charged));
  }
  if (r == 0) ctx.deliver_image(0, std::move(fb));
}

void paste_at_node0(NodeContext& ctx, const Framebuffer& part) {
  auto ph = ctx.phase("paste");
  // The node's rows (a strip or interleaved) are one contiguous array of its frame buffer, sent
  // in place to node 0, which displays them: no packing is charged. Only colour travels (ch. V);
  // the picture and its depth map are the rows each node rendered, handed over once sent (the
  // colour node 0 receives is these rows' colour, byte for byte).
  (void)coll::gatherv(ctx.comm(), 0, part.rgb());
  (void)coll::gatherv(
      ctx.comm(), 0,
      pack(std::vector<int>{part.rows().begin, part.rows().end, part.rows().stride}));
  ctx.deliver_rows(0, part);
}

} // namespace zc::blazek
