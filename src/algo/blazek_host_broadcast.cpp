// Blazek 1991, ch. V "Host Broadcast": every object goes to every node (the host hands the
// descriptions to node 0, which broadcasts them hierarchically in log2 P steps); each node keeps
// only what touches its rows and renders it; rows are strips of H/P, or interleaved (row y to
// node y mod P); the partial images are pasted.
#include <cstring>

#include "algo/blazek_common.hpp"
#include "algo/blazek_culling.hpp"
#include "algo/blazek_merge_paste.hpp"
#include "algo/blazek_mesh.hpp"
#include "algo/blazek_methods.hpp"
#include "algo/blazek_render.hpp"
#include "algo/blazek_wire.hpp"
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
  Message all{{}, sizeof(std::uint32_t)};
  const std::uint32_t n = std::uint32_t(s.objects.size());
  append(all.payload, &n, 1);
  for (std::size_t o = 0; o < s.objects.size(); ++o) {
    Message b = encode_object(s, o);
    const std::uint32_t sz = std::uint32_t(b.payload.size());
    append(all.payload, &sz, 1);
    append(all.payload, b.payload.data(), b.payload.size());
    all.charged += b.charged;
  }
  ctx.charge_packing(all.charged);
  ctx.comm().send(0, kTagHost, std::move(all));
}

void host_broadcast_node(NodeContext& ctx) {
  check_scene(ctx.scene());
  Comm& c = ctx.comm();
  const int P = c.size(), r = c.rank();
  const std::string lines = ctx.options().get("lines");
  if (lines != "strips" && lines != "interleaved")
    throw UsageError("--lines must be strips or interleaved");
  const NodeRenderer nr(ctx.scene());
  const int H = nr.height();
  Message scene;
  {
    auto ph = ctx.phase("broadcast");
    if (r == 0) scene = c.recv_message(c.host_rank(), kTagHost);
    scene = coll::broadcast(c, 0, std::move(scene));
  }
  const Bytes& all = scene.payload;
  const RowSet rows = lines == "strips" ? strip_rows(r, P, H) : RowSet::interleaved(r, P, H);
  Framebuffer fb = nr.make_framebuffer(rows);
  ctx.alloc(frame_buffer_bytes(fb) + double(scene.charged), "rows frame buffer and scene");
  {
    auto ph = ctx.phase("render");
    std::uint32_t n = 0, at = 4;
    std::memcpy(&n, all.data(), 4);
    for (std::uint32_t o = 0; o < n; ++o) {
      std::uint32_t sz;
      std::memcpy(&sz, all.data() + at, 4);
      Bytes b(all.begin() + at + 4, all.begin() + at + 4 + sz);
      at += 4 + sz;
      std::uint32_t count = 0;
      if (!object_may_touch(nr, b, rows, count)) {
        // "When a node receives an object from the host, it tessellates the object into polygons
        // ... Polygons lying wholly outside of the node's portion of the frame buffer are
        // discarded at this time" (ch. V): tessellated and tested, not transformed and shaded,
        // which is rendering, the part that shrinks with P (ch. VI: "the time to tessellate the
        // broadcast objects remains constant, while the time spent rendering decreases"). The
        // counts are charged without computing polygons that cannot land in the node's rows.
        Counters k;
        k.triangles_tessellated = count;
        k.triangles_estimated = count;
        ctx.charge(k);
        continue;
      }
      const Mesh m = object_mesh(ctx, b);
      const ProjectedMesh pm(ctx, nr, m);
      const Held held(ctx, m.bytes() + double(pm.pv.size() * sizeof(ProjectedVertex)), "polygons");
      // "Polygons lying wholly outside of the node's portion of the frame buffer are discarded".
      const auto keep = triangles_touching(ctx, nr, pm, rows);
      render_mesh(ctx, nr, pm, fb, &keep);
    }
  }
  paste_at_node0(ctx, fb);
}

} // namespace zc::blazek
