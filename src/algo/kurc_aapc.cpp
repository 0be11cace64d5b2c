// Kurc, Aykanat, Ozguc §3.2: pixel merging by all-to-all personalised communication (AAPC). Every
// subregion's pixels go straight to its owner (pairwise e-cube schedule over disjoint paths), then
// the local and received pixels are z-buffered into the owned scanlines.
#include "algo/kurc_active_merging.hpp"

#include <algorithm>

#include "comm/collectives.hpp"

namespace zc::kurc {

namespace {

class AllToAllPersonalized : public ActivePixelMerging {
public:
  using ActivePixelMerging::ActivePixelMerging;
  const char* name() const override { return "aapc"; }

protected:
  void exchange(NodeContext& ctx, const std::vector<int>& owner, MergeMeasures& m,
                Counters& w) override {
    Comm& c = ctx.comm();
    const int P = c.size(), r = c.rank(), H = int(owner.size());
    // §3.2: "Each processor holds a local z-buffer of size N x N/P" (its owned scanlines).
    std::uint64_t owned_rows = 0;
    for (int node : owner)
      owned_rows += node == r;
    ctx.alloc(double(owned_rows) * width_ * double(records::kurc::kZbufferLocation),
              "z-buffer of the owned scanlines");
    std::vector<Message> out;
    for (auto& b : serialize_sparse_by_owner(wpa_, owner, P))
      out.push_back(sparse_message(std::move(b)));
    std::vector<int> runs(std::size_t(P), 0); // runs of owned scanlines per destination
    for (int y = 0; y < H; ++y)
      if (owner[y] >= 0 && owner[y] < P)
        runs[std::size_t(owner[y])] += y == 0 || owner[y - 1] != owner[y];
    double gathered = 0; // send buffers gathered from several runs of scanlines (copies)
    for (int k = 0; k < P; ++k)
      if (k != r && runs[std::size_t(k)] > 1) gathered += double(out[k].charged);
    w.bytes_packed += std::uint64_t(gathered);
    ctx.alloc(gathered, "send buffers");
    // Step k of the schedule exchanges with node r ^ k.
    m.step_bytes.assign(std::size_t(std::max(0, P - 1)), 0.0);
    for (int k = 1; k < P; ++k)
      m.step_bytes[k - 1] = double(out[r ^ k].charged);
    auto msgs = coll::alltoallv(c, std::move(out), coll::AllToAll::Pairwise);
    double received = 0; // every other node's pixels are held until merged
    std::vector<Bytes> in;
    for (int k = 0; k < P; ++k) {
      if (k != r) received += double(msgs[k].charged);
      in.push_back(std::move(msgs[k].payload));
    }
    ctx.alloc(received, "receive buffers");
    ctx.release(gathered);
    // The local pixels first, then every other node's in rank order, merged into the owned rows.
    std::vector<const Bytes*> order{&in[r]};
    for (int k = 0; k < P; ++k)
      if (k != r) order.push_back(&in[k]);
    std::vector<std::uint64_t> counts;
    mine_ = merge_sparse(order, width_, 0, H, counts);
    const std::uint64_t local_pixels = counts[0];
    std::uint64_t received_pixels = 0;
    for (std::size_t i = 1; i < counts.size(); ++i)
      received_pixels += counts[i];
    m.merge_load += received_pixels;
    // §3.2: "Local pixels are scattered onto the z-buffer without any distance comparisons. Then,
    // each received pixel's z value is compared with the z value in the pixel location": one
    // operation a local pixel and one a received pixel, whatever the number of senders.
    w.merge_ops += local_pixels + received_pixels;
    ctx.release(received);
  }
};

} // namespace

std::unique_ptr<MergeScheme> make_aapc(const ScreenPartition& partition) {
  return std::make_unique<AllToAllPersonalized>(partition);
}

} // namespace zc::kurc
