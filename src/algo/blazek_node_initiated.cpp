// Blazek 1991, ch. V "Node Initiated Method": the host sends only primitive descriptions (about
// 100 bytes each) round-robin; the nodes tessellate and render them, then merge hierarchically.
#include "algo/blazek_common.hpp"
#include "algo/blazek_host_messages.hpp"
#include "algo/blazek_methods.hpp"
#include "algo/blazek_wire.hpp"

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

void node_initiated_node(NodeContext& ctx) {
  render_host_messages_then_merge(ctx, true, false,
                                  [&](const Bytes& b) { return object_mesh(ctx, b); });
}

} // namespace zc::blazek
