// Blazek 1991, ch. V "Node Initiated with Object Forwarding": node k owns the strip of rows
// [kH/P, (k+1)H/P). Descriptions arrive round-robin from the host; a node renders what falls in
// its strip and forwards to the owners of the other strips what falls there: the description to
// be re-tessellated (--forward object) or the tessellated polygons (--forward polygons). Strips
// are pasted, not merged.
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

void object_forwarding_node(NodeContext& ctx) {
  check_scene(ctx.scene());
  Comm& c = ctx.comm();
  const int P = c.size(), r = c.rank();
  const std::string mode = ctx.options().get("forward");
  if (mode != "object" && mode != "polygons")
    throw UsageError("--forward must be object or polygons");
  const NodeRenderer nr(ctx.scene());
  const int H = nr.height();
  auto strip_of = [&](int y) { return strip_of_row(y, P, H); };
  const RowSet mine = strip_rows(r, P, H);
  Framebuffer fb = nr.make_framebuffer(mine);
  ctx.alloc(frame_buffer_bytes(fb), "strip frame buffer");
  std::uint64_t forwarded = 0;
  std::vector<SendHandle> sends;
  {
    auto ph = ctx.phase("render");
    for (;;) {
      const Message got = c.recv_message(c.host_rank(), kTagHost);
      const Bytes& b = got.payload;
      if (is_end(b)) break;
      const Held msg(ctx, double(got.charged), "host message");
      const Mesh m = object_mesh(ctx, b);
      const ProjectedMesh pm(ctx, nr, m);
      const Held held(ctx, m.bytes() + double(pm.pv.size() * sizeof(ProjectedVertex)), "polygons");
      // Which strips each polygon (or a portion of it) lies in.
      std::vector<std::uint32_t> own;
      std::vector<std::vector<std::uint32_t>> others(P);
      const auto n = std::uint32_t(m.tris.size());
      for (std::uint32_t t = 0; t < n; ++t) {
        int y0, y1;
        if (!pm.rows(nr, t, y0, y1)) continue;
        for (int s = strip_of(y0); s <= strip_of(y1); ++s)
          (s == r ? own : others[s]).push_back(t);
      }
      Counters k;
      k.triangles_estimated = n;
      ctx.charge(k);
      for (int s = 0; s < P; ++s)
        if (!others[s].empty()) {
          ++forwarded;
          sends.push_back(c.isend(s, kTagForward,
                                  mode == "object" ? got : polygon_packet(polys_of(m, others[s]))));
        }
      render_mesh(ctx, nr, pm, fb, &own);
    }
    for (int n = 0; n < P; ++n)
      if (n != r) sends.push_back(c.isend(n, kTagForward, Bytes{}));
    // Forwarded work, until every other node has said it is done.
    for (int ends = 0; ends < P - 1;) {
      const Message got = c.recv_message(kAnySource, kTagForward);
      const Bytes& b = got.payload;
      if (is_end(b)) {
        ++ends;
        continue;
      }
      const Held msg(ctx, double(got.charged), "forwarded message");
      if (mode == "object") {
        // Re-tessellated; only the polygons in this strip are rendered.
        const Mesh m = object_mesh(ctx, b);
        const ProjectedMesh pm(ctx, nr, m);
        const Held held(ctx, m.bytes() + double(pm.pv.size() * sizeof(ProjectedVertex)),
                        "polygons");
        const auto mine_only = triangles_touching(ctx, nr, pm, mine);
        render_mesh(ctx, nr, pm, fb, &mine_only);
      } else {
        const Mesh m = mesh_of(unpack<Poly>(b));
        render_mesh(ctx, nr, ProjectedMesh(ctx, nr, m), fb);
      }
    }
    for (auto& h : sends)
      h->wait();
  }
  auto total =
      coll::reduce(c, 0, std::vector<std::int64_t>{std::int64_t(forwarded)}, coll::Op::Sum);
  if (r == 0) ctx.metrics()["blazek"] = {{"forwarded_messages", total[0]}, {"forward", mode}};
  paste_at_node0(ctx, fb);
}

} // namespace zc::blazek
