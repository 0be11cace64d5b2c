// Blazek 1991, ch. V "Host Initiated Method": the host tessellates the primitives and sends
// polygon packets of N polygons round-robin to the nodes; each node renders into its own full
// frame buffer; the buffers are merged hierarchically (Algorithm 4, Figure 10).
#include <algorithm>
#include <string>

#include "algo/blazek_common.hpp"
#include "algo/blazek_host_messages.hpp"
#include "algo/blazek_methods.hpp"
#include "algo/blazek_wire.hpp"
#include "comm/wire.hpp"
#include "util/error.hpp"

namespace zc::blazek {

int packet_size(const NodeContext& ctx) {
  return std::stoi(ctx.options().get("packet")); // 10..1000, checked by validate_options
}

void host_initiated_host(NodeContext& ctx) {
  const Scene& s = ctx.scene();
  check_scene(s);
  Comm& c = ctx.comm();
  const int P = c.size(), N = packet_size(ctx);
  auto ph = ctx.phase("distribute");
  std::vector<Poly> packet;
  std::vector<int> sent(std::size_t(P), 0);
  int next = 0;
  auto flush = [&] {
    if (packet.empty()) return;
    // Flow control: wait until the node has rendered packet i - kHostWindow.
    if (sent[std::size_t(next)]++ >= kHostWindow) c.recv(next, kTagAck);
    Message m = polygon_packet(packet);
    ctx.charge_packing(m.charged);
    // Blocking: the host waits for each packet to reach its node (the SRM has one link, to node
    // 0); a node buffers up to kHostWindow packets it has not rendered yet.
    c.send(next, kTagHost, std::move(m));
    next = (next + 1) % P;
    packet.clear();
  };
  for (std::size_t o = 0; o < s.objects.size(); ++o) {
    Counters k; // the host's tessellation, on the host's CPU (node 0's cost table)
    for (const Poly& p : host_polygons(s, o, k)) {
      packet.push_back(p);
      if (int(packet.size()) == N) flush();
    }
    ctx.charge(k);
  }
  flush();
  for (int n = 0; n < P; ++n)
    c.send(n, kTagHost, Bytes{});
  for (int n = 0; n < P; ++n) // the acknowledgements still due
    for (int i = 0; i < std::min(sent[std::size_t(n)], kHostWindow); ++i)
      c.recv(n, kTagAck);
}

void host_initiated_node(NodeContext& ctx) {
  render_host_messages_then_merge(ctx, false, true,
                                  [&](const Bytes& b) { return mesh_of(unpack<Poly>(b)); });
}

} // namespace zc::blazek
