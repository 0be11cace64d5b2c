// Blazek 1991, ch. V "Node Initiated Method": "the host distributes only the primitive's
// description to the nodes in a round-robin fashion" (object description packets, about 100 bytes
// each); each node tessellates and renders them into its own full frame buffer; the frame buffers
// are merged hierarchically, as in the host initiated method.
#include "algo/blazek/blazek_common.hpp"
#include "algo/blazek/blazek_host_messages.hpp"
#include "algo/blazek/blazek_merge_paste.hpp"
#include "algo/blazek/blazek_mesh.hpp"
#include "algo/blazek/blazek_methods.hpp"
#include "algo/blazek/blazek_render.hpp"
#include "algo/blazek/blazek_wire.hpp"

namespace zc::blazek {

// Host side shared by node initiated and object forwarding: descriptions round-robin, then an
// end marker to every node.
void describe_round_robin(NodeContext& ctx) {
  const Scene& s = ctx.scene();
  check_scene(s);
  Comm& c = ctx.comm();
  auto ph = ctx.phase("distribute");
  for (std::size_t o = 0; o < s.objects.size(); ++o) {
    Message m = encode_object(s, o);
    ctx.charge_packing(m.charged);
    c.send(int(o % std::size_t(c.size())), kTagHost, std::move(m));
  }
  for (int n = 0; n < c.size(); ++n)
    c.send(n, kTagHost, Bytes{});
}

// It "moves the tessellation process from the host to the nodes": each description is tessellated,
// its polygons held while they are rendered into the node's full frame buffer.
void node_initiated_node(NodeContext& ctx) {
  check_scene(ctx.scene());
  const NodeRenderer nr(ctx.scene(), ctx.scene().camera, ctx.scene_facts().bounds);
  Framebuffer fb;
  {
    auto ph = ctx.phase("render"); // the clear of the new frame buffer is the phase's
    fb = full_frame_buffer(ctx, nr);
    for_each_host_message(ctx, [&](const Message& description) {
      const Mesh m = object_mesh(ctx, description.payload);
      const Held held(ctx, tessellation_bytes(m), "polygons");
      render_mesh(ctx, nr, ProjectedMesh(ctx, nr, m), fb);
    });
  }
  hierarchical_merge(ctx, std::move(fb));
}

} // namespace zc::blazek
