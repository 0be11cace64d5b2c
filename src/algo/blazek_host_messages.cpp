// Blazek 1991, ch. V "Host Initiated Method" and "Node Initiated Method": the node's loop over the
// host's messages (blazek_host_messages.hpp).
#include "algo/blazek_host_messages.hpp"

#include <deque>

#include "algo/blazek_common.hpp"
#include "algo/blazek_merge_paste.hpp"
#include "algo/blazek_render.hpp"
#include "algo/blazek_wire.hpp"

namespace zc::blazek {

void render_host_messages_then_merge(NodeContext& ctx, bool tessellates, bool acknowledge,
                                     const std::function<Mesh(const Bytes&)>& mesh_of_message) {
  check_scene(ctx.scene());
  const NodeRenderer nr(ctx.scene());
  Framebuffer fb;
  {
    auto ph = ctx.phase("render"); // the clear of the new frame buffer is the phase's
    fb = nr.make_framebuffer(RowSet::all(nr.height()));
    ctx.alloc(frame_buffer_bytes(fb), "frame buffer");
    Counters k;
    k.pixels_cleared = fb.pixel_count();
    ctx.charge(k);
    std::deque<SendHandle> acks;
    for (;;) {
      const Message got = ctx.comm().recv_message(ctx.comm().host_rank(), kTagHost);
      const Bytes& b = got.payload;
      if (is_end(b)) break;
      const Held msg(ctx, double(got.charged), "host message");
      const Mesh m = mesh_of_message(b);
      // Host initiated renders out of the packet itself; node initiated holds the tessellation
      // (the projected vertices are counted with it).
      const Held held(
          ctx, tessellates ? m.bytes() + double(m.vertices.size() * sizeof(ProjectedVertex)) : 0.0,
          "polygons");
      render_mesh(ctx, nr, ProjectedMesh(ctx, nr, m), fb);
      if (acknowledge) {
        acks.push_back(ctx.comm().isend(ctx.comm().host_rank(), kTagAck, Bytes(4)));
        if (acks.size() > std::size_t(kHostWindow)) {
          acks.front()->wait();
          acks.pop_front();
        }
      }
    }
    for (auto& a : acks)
      a->wait();
  }
  hierarchical_merge(ctx, std::move(fb));
}

} // namespace zc::blazek
