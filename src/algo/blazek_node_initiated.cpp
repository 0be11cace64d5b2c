// Blazek 1991, ch. V "Node Initiated Method": the host sends only primitive descriptions (about
// 100 bytes each) round-robin; the nodes tessellate and render them, then merge hierarchically.
#include "algo/blazek_common.hpp"
#include "algo/blazek_methods.hpp"

namespace zc::blazek {

// Host side shared by node initiated and object forwarding: descriptions round-robin, then an
// end marker to every node.
void describe_round_robin(NodeContext& ctx) {
  const Scene& s = ctx.scene();
  check_scene(s);
  Comm& c = ctx.comm();
  auto ph = ctx.phase("distribute");
  for (std::size_t o = 0; o < s.objects.size(); ++o) {
    Bytes b = encode_object(s, o);
    Counters k;
    k.bytes_packed = b.size();
    ctx.charge(k);
    c.send(int(o % std::size_t(c.size())), kTagHost, std::move(b));
  }
  for (int n = 0; n < c.size(); ++n)
    c.send(n, kTagHost, Bytes{});
}

void node_initiated_node(NodeContext& ctx) {
  check_scene(ctx.scene());
  const NodeRenderer nr(ctx.scene());
  Framebuffer fb = nr.make_framebuffer(RowSet::all(nr.height()));
  ctx.alloc(double(fb.bytes()), "frame buffer");
  {
    auto ph = ctx.phase("render");
    Counters k;
    k.pixels_cleared = fb.pixel_count();
    ctx.charge(k);
    for (;;) {
      Bytes b = ctx.comm().recv(ctx.comm().host_rank(), kTagHost);
      if (is_end(b)) break;
      render_polygons(ctx, nr, object_polygons(ctx, b), fb);
    }
  }
  hierarchical_merge(ctx, std::move(fb));
}

} // namespace zc::blazek
