// Blazek 1991, ch. V "Host Initiated Method": the host tessellates the primitives and sends
// polygon packets of N polygons round-robin to the nodes; each node renders into its own full
// frame buffer; the buffers are merged hierarchically (Algorithm 4, Figure 10).
#include <string>

#include "algo/blazek_common.hpp"
#include "algo/blazek_methods.hpp"
#include "comm/wire.hpp"
#include "util/error.hpp"

namespace zc::blazek {

int packet_size(const NodeContext& ctx) {
  const std::string v = ctx.options().get("packet", "100");
  int n = 0;
  try {
    n = std::stoi(v);
  } catch (...) {
  }
  if (n < 1 || n > 100000) throw UsageError("--packet '" + v + "': expected 1..100000 polygons");
  return n;
}

void host_initiated_host(NodeContext& ctx) {
  const Scene& s = ctx.scene();
  check_scene(s);
  Comm& c = ctx.comm();
  const int P = c.size(), N = packet_size(ctx);
  auto ph = ctx.phase("distribute");
  std::vector<Poly> packet;
  int next = 0;
  auto flush = [&] {
    if (packet.empty()) return;
    Counters k;
    k.bytes_packed = packet.size() * sizeof(Poly);
    ctx.charge(k);
    c.send(next, kTagHost, pack(packet)); // the host waits for each packet to leave (one link)
    next = (next + 1) % P;
    packet.clear();
  };
  for (std::size_t o = 0; o < s.objects.size(); ++o) {
    Counters k;
    for (const Poly& p : host_polygons(s, o, k)) {
      packet.push_back(p);
      if (int(packet.size()) == N) flush();
    }
    ctx.charge(k);
  }
  flush();
  for (int n = 0; n < P; ++n)
    c.send(n, kTagHost, Bytes{});
}

void host_initiated_node(NodeContext& ctx) {
  render_host_messages_then_merge(ctx, [&](const Bytes& b) { return unpack<Poly>(b); });
}

} // namespace zc::blazek
