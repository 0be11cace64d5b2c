// Blazek 1991, ch. V "Node Initiated with Object Forwarding": node k owns the strip of rows
// [kH/P, (k+1)H/P). Descriptions arrive round-robin from the host; a node renders what falls in
// its strip and forwards to the owners of the other strips what falls there: the description to
// be re-tessellated (--forward object) or the tessellated polygons (--forward polygons). Strips
// are pasted, not merged.
#include <nlohmann/json.hpp>

#include "algo/blazek/blazek_common.hpp"
#include "algo/blazek/blazek_culling.hpp"
#include "algo/blazek/blazek_host_messages.hpp"
#include "algo/blazek/blazek_merge_paste.hpp"
#include "algo/blazek/blazek_mesh.hpp"
#include "algo/blazek/blazek_methods.hpp"
#include "algo/blazek/blazek_render.hpp"
#include "algo/blazek/blazek_wire.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "util/error.hpp"

namespace zc::blazek {

namespace {
// A node of the method: its strip of the frame buffer, what it forwards, and its sends.
struct StripNode {
  NodeContext& ctx;
  const NodeRenderer& nr;
  bool forward_objects; // --forward object: descriptions; polygons: the tessellated polygons
  Framebuffer fb;       // the node's strip
  std::vector<SendHandle> sends;
  std::uint64_t forwarded = 0;
};

// "If a polygon (or a portion of a polygon) is found to lie in an different strip of the image than
// the one assigned to the node": the polygons of the node's own strip, and those of each other.
struct ByStrip {
  std::vector<std::uint32_t> own;
  std::vector<std::vector<std::uint32_t>> others;
};
ByStrip split_by_strip(StripNode& n, const ProjectedMesh& pm) {
  const int P = n.ctx.comm().size(), r = n.ctx.comm().rank(), H = n.nr.height();
  ByStrip out{{}, std::vector<std::vector<std::uint32_t>>(std::size_t(P))};
  const auto count = std::uint32_t(pm.mesh.tris.size());
  for (std::uint32_t t = 0; t < count; ++t) {
    int y0, y1;
    if (!pm.rows(n.nr, t, y0, y1)) continue;
    for (int s = strip_of_row(y0, P, H); s <= strip_of_row(y1, P, H); ++s)
      (s == r ? out.own : out.others[std::size_t(s)]).push_back(t);
  }
  Counters k;
  k.triangles_estimated = count;
  n.ctx.charge(k);
  return out;
}

// An object from the host: tessellated, forwarded to the owners of the other strips it touches
// ("then the object description is forwarded", or its polygons), rendered in the node's strip.
void render_and_forward(StripNode& n, const Message& description) {
  const Mesh m = object_mesh(n.ctx, description.payload);
  const ProjectedMesh pm(n.ctx, n.nr, m);
  const Held held(n.ctx, tessellation_bytes(m), "polygons");
  const ByStrip strips = split_by_strip(n, pm);
  for (std::size_t s = 0; s < strips.others.size(); ++s)
    if (!strips.others[s].empty()) {
      ++n.forwarded;
      n.sends.push_back(n.ctx.comm().isend(
          int(s), kTagForward,
          n.forward_objects ? description : polygon_packet(polys_of(m, strips.others[s]))));
    }
  render_mesh(n.ctx, n.nr, pm, n.fb, &strips.own);
}

// Forwarded work: a description is re-tessellated and only its polygons in the node's strip are
// rendered; forwarded polygons are all in it.
void render_forwarded(StripNode& n, const Bytes& b) {
  if (n.forward_objects) {
    const Mesh m = object_mesh(n.ctx, b);
    const ProjectedMesh pm(n.ctx, n.nr, m);
    const Held held(n.ctx, tessellation_bytes(m), "polygons");
    const auto mine = triangles_touching(n.ctx, n.nr, pm, n.fb.rows());
    render_mesh(n.ctx, n.nr, pm, n.fb, &mine);
  } else {
    const Mesh m = mesh_of(unpack<Poly>(b));
    render_mesh(n.ctx, n.nr, ProjectedMesh(n.ctx, n.nr, m), n.fb);
  }
}

// The node's end marker to every other node, then forwarded work until every other node has said
// it is done.
void render_forwarded_until_all_done(StripNode& n) {
  Comm& c = n.ctx.comm();
  for (int k = 0; k < c.size(); ++k)
    if (k != c.rank()) n.sends.push_back(c.isend(k, kTagForward, Bytes{}));
  for (int ends = 0; ends < c.size() - 1;) {
    const Message got = c.recv_message(kAnySource, kTagForward);
    if (is_end(got.payload)) {
      ++ends;
      continue;
    }
    const Held msg(n.ctx, double(got.charged), "forwarded message");
    render_forwarded(n, got.payload);
  }
}

bool forwards_objects(const NodeContext& ctx) {
  const std::string mode = ctx.options().get("forward");
  if (mode != "object" && mode != "polygons")
    throw UsageError("--forward must be object or polygons");
  return mode == "object";
}
} // namespace

// "The frame buffer is decomposed into strips": node k keeps rows [kH/P, (k+1)H/P) only; objects
// come from the host round-robin, are rendered in the node's strip and forwarded to the owners of
// the others; "the partial node images are pasted together rather than merged".
void object_forwarding_node(NodeContext& ctx) {
  check_scene(ctx.scene());
  Comm& c = ctx.comm();
  const bool objects = forwards_objects(ctx);
  const NodeRenderer nr(ctx.scene(), ctx.scene().camera, ctx.scene_facts().bounds);
  StripNode n{ctx, nr, objects, nr.make_framebuffer(strip_rows(c.rank(), c.size(), nr.height())),
              {},  0};
  ctx.alloc(frame_buffer_bytes(n.fb), "strip frame buffer");
  {
    auto ph = ctx.phase("render");
    for_each_host_message(ctx,
                          [&](const Message& description) { render_and_forward(n, description); });
    render_forwarded_until_all_done(n);
    for (auto& h : n.sends)
      h->wait();
  }
  auto total =
      coll::reduce(c, 0, std::vector<std::int64_t>{std::int64_t(n.forwarded)}, coll::Op::Sum);
  if (c.rank() == 0)
    ctx.metrics()["blazek"] = {{"forwarded_messages", total[0]},
                               {"forward", objects ? "object" : "polygons"}};
  paste_at_node0(ctx, n.fb);
}

} // namespace zc::blazek
