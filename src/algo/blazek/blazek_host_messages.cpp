// Blazek 1991, ch. V: the node's loop over the host's messages, and the full frame buffer of host
// initiated and node initiated (blazek_host_messages.hpp).
#include "algo/blazek/blazek_host_messages.hpp"

#include "algo/blazek/blazek_common.hpp"
#include "algo/blazek/blazek_wire.hpp"

namespace zc::blazek {

Framebuffer full_frame_buffer(NodeContext& ctx, const NodeRenderer& nr) {
  Framebuffer fb = nr.make_framebuffer(RowSet::all(nr.height()));
  ctx.alloc(frame_buffer_bytes(fb), "frame buffer");
  Counters k;
  k.pixels_cleared = fb.pixel_count();
  ctx.charge(k);
  return fb;
}

void for_each_host_message(NodeContext& ctx, const std::function<void(const Message&)>& render) {
  for (;;) {
    const Message got = ctx.comm().recv_message(ctx.comm().host_rank(), kTagHost);
    if (is_end(got.payload)) return;
    const Held msg(ctx, double(got.charged), "host message");
    render(got);
  }
}

} // namespace zc::blazek
