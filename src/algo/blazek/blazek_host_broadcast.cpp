// Blazek 1991, ch. V "Host Broadcast": every object goes to every node (the host hands the
// descriptions to node 0, which broadcasts them hierarchically in log2 P steps); each node keeps
// only what touches its rows and renders it; rows are strips of H/P, or interleaved (row y to
// node y mod P); the partial images are pasted.
#include <string>

#include "algo/blazek/blazek_common.hpp"
#include "algo/blazek/blazek_culling.hpp"
#include "algo/blazek/blazek_merge_paste.hpp"
#include "algo/blazek/blazek_mesh.hpp"
#include "algo/blazek/blazek_methods.hpp"
#include "algo/blazek/blazek_render.hpp"
#include "algo/blazek/blazek_wire.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "util/error.hpp"

namespace zc::blazek {

void host_broadcast_host(NodeContext& ctx) {
  const Scene& s = ctx.scene();
  check_scene(s);
  auto ph = ctx.phase("distribute");
  // All descriptions in one message: u32 count, then (u32 size, bytes) per object; charged as the
  // thesis's description packets (records.hpp) and the count.
  RecordWriter all;
  std::size_t charged = sizeof(std::uint32_t);
  all.put(std::uint32_t(s.objects.size()));
  for (std::size_t o = 0; o < s.objects.size(); ++o) {
    const Message b = encode_object(s, o);
    all.put_sized(b.payload);
    charged += b.charged;
  }
  ctx.charge_packing(charged);
  ctx.comm().send(0, kTagHost, Message{std::move(all).take(), charged});
}

namespace {
// "Another advantage lies in the fact that the frame buffer is not required to be decomposed in a
// contiguous manner": strips of H/P rows, or scan-lines interleaved (row y to node y mod P).
RowSet rows_of_node(NodeContext& ctx, int H) {
  const std::string lines = ctx.options().get("lines");
  if (lines != "strips" && lines != "interleaved")
    throw UsageError("--lines must be strips or interleaved");
  const int P = ctx.comm().size(), r = ctx.comm().rank();
  return lines == "strips" ? strip_rows(r, P, H) : RowSet::interleaved(r, P, H);
}

// "The host ... broadcasts all the objects to all the nodes": to node 0, which broadcasts them
// hierarchically in log2 P steps.
Message receive_broadcast(NodeContext& ctx) {
  Comm& c = ctx.comm();
  auto ph = ctx.phase("broadcast");
  Message scene;
  if (c.rank() == 0) scene = c.recv_message(c.host_rank(), kTagHost);
  return coll::broadcast(c, 0, std::move(scene));
}

// "When a node receives an object from the host, it tessellates the object into polygons ...
// Polygons lying wholly outside of the node's portion of the frame buffer are discarded at this
// time" (ch. V): an object that cannot touch the node's rows is tessellated and tested, not
// transformed and shaded, which is rendering, the part that shrinks with P (ch. VI: "the time to
// tessellate the broadcast objects remains constant, while the time spent rendering decreases").
// Its counts are charged without computing polygons that cannot land in the node's rows.
void render_if_touching(NodeContext& ctx, const NodeRenderer& nr, Framebuffer& fb,
                        const Bytes& description) {
  std::uint32_t count = 0;
  if (!object_may_touch(nr, description, fb.rows(), count)) {
    Counters k;
    k.triangles_tessellated = count;
    k.triangles_estimated = count;
    ctx.charge(k);
    return;
  }
  const Mesh m = object_mesh(ctx, description);
  const ProjectedMesh pm(ctx, nr, m);
  const Held held(ctx, tessellation_bytes(m), "polygons");
  const auto keep = triangles_touching(ctx, nr, pm, fb.rows());
  render_mesh(ctx, nr, pm, fb, &keep);
}
} // namespace

void host_broadcast_node(NodeContext& ctx) {
  check_scene(ctx.scene());
  const NodeRenderer nr(ctx.scene(), ctx.scene().camera, ctx.scene_facts().bounds);
  const RowSet rows = rows_of_node(ctx, nr.height());
  const Message scene = receive_broadcast(ctx);
  Framebuffer fb = nr.make_framebuffer(rows);
  ctx.alloc(frame_buffer_bytes(fb) + double(scene.charged), "rows frame buffer and scene");
  {
    auto ph = ctx.phase("render");
    RecordReader descriptions(scene.payload, "host broadcast");
    const auto n = descriptions.get<std::uint32_t>();
    for (std::uint32_t o = 0; o < n; ++o)
      render_if_touching(ctx, nr, fb, descriptions.get_sized());
  }
  paste_at_node0(ctx, fb);
}

} // namespace zc::blazek
