// Blazek 1991, ch. V "Host Initiated Method": the host tessellates the primitives and sends
// polygon packets of N polygons round-robin to the nodes; each node renders into its own full
// frame buffer; the buffers are merged hierarchically (Algorithm 4, Figure 10).
#include <algorithm>
#include <deque>
#include <string>

#include "algo/blazek/blazek_common.hpp"
#include "algo/blazek/blazek_host_messages.hpp"
#include "algo/blazek/blazek_merge_paste.hpp"
#include "algo/blazek/blazek_mesh.hpp"
#include "algo/blazek/blazek_methods.hpp"
#include "algo/blazek/blazek_render.hpp"
#include "algo/blazek/blazek_wire.hpp"
#include "comm/wire.hpp"
#include "util/error.hpp"

namespace zc::blazek {

namespace {
// Flow control: a node buffers at most this many unconsumed polygon packets (its message buffers
// are part of its few megabytes); it acknowledges each packet it has rendered, and the host waits
// for the acknowledgement of packet i - kHostWindow before sending packet i to the same node. (An
// assumption: the thesis does not say how its host was throttled.)
constexpr int kHostWindow = 4;

// A node's acknowledgements to the host, at most kHostWindow of them in flight.
class Acknowledgements {
public:
  explicit Acknowledgements(NodeContext& ctx) : ctx_(ctx) {}
  void rendered() {
    acks_.push_back(ctx_.comm().isend(ctx_.comm().host_rank(), kTagAck, Bytes(4)));
    if (acks_.size() > std::size_t(kHostWindow)) {
      acks_.front()->wait();
      acks_.pop_front();
    }
  }
  void wait_all() {
    for (auto& a : acks_)
      a->wait();
  }

private:
  NodeContext& ctx_;
  std::deque<SendHandle> acks_;
};
} // namespace

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

// "After all packets have been received and processed, the frame buffers are then merged
// hierarchically": each packet is rendered out of the message itself (no copy of its polygons
// held) into the node's full frame buffer, and acknowledged.
void host_initiated_node(NodeContext& ctx) {
  check_scene(ctx.scene());
  const NodeRenderer nr(ctx.scene(), ctx.scene().camera, ctx.scene_facts().bounds);
  Framebuffer fb;
  {
    auto ph = ctx.phase("render"); // the clear of the new frame buffer is the phase's
    fb = full_frame_buffer(ctx, nr);
    Acknowledgements acks(ctx);
    for_each_host_message(ctx, [&](const Message& packet) {
      const Mesh m = mesh_of(unpack<Poly>(packet.payload));
      render_mesh(ctx, nr, ProjectedMesh(ctx, nr, m), fb);
      acks.rendered();
    });
    acks.wait_all();
  }
  hierarchical_merge(ctx, std::move(fb));
}

} // namespace zc::blazek
