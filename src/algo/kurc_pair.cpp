// Kurc, Aykanat, Ozguc §3.1: pixel merging by pairwise exchange (PAIR). d divide-and-exchange
// stages; at stage i a node keeps the scanlines whose owner agrees with it on bit i, sends the
// others over channel i, and merges what arrives.
#include "algo/kurc_active_merging.hpp"

namespace zc::kurc {

namespace {

class PairwiseExchange : public ActivePixelMerging {
public:
  using ActivePixelMerging::ActivePixelMerging;
  const char* name() const override { return "pair"; }

protected:
  void exchange(NodeContext& ctx, const std::vector<int>& owner, MergeMeasures& m,
                Counters& w) override {
    Comm& c = ctx.comm();
    const int r = c.rank(), H = int(owner.size());
    mine_ = std::move(wpa_);
    double held = wpa_record_bytes(mine_); // the WPA, charged by local_zbuffer
    for (int i = 0; i < c.dimension(); ++i) {
      const int bit = 1 << i, partner = r ^ bit;
      const auto leaves = [&](int y) { return (owner[y] & bit) != (r & bit); };
      auto give = select_rows(mine_, leaves);
      auto keep = select_rows(mine_, [&](int y) { return !leaves(y); });
      Message out = sparse_message(serialize_sparse(give));
      // A message gathered from several runs of scanlines is a copy: packed, and held until sent.
      const double gathered = fragmented(H, leaves) ? double(out.charged) : 0.0;
      w.bytes_packed += std::uint64_t(gathered);
      ctx.alloc(gathered, "send buffer");
      m.step_bytes.push_back(double(out.charged));
      auto h = c.isend(partner, kTagPair + i, std::move(out));
      const Message msg = c.recv_message(partner, kTagPair + i);
      const Bytes& in = msg.payload;
      const double received = double(msg.charged);
      ctx.alloc(received, "receive buffer");
      h->wait();
      ActivePixels got = deserialize_sparse(in.data(), in.size(), width_, 0, H);
      m.merge_load += got.count();
      // Retained and received pixels merge into a new array, which replaces the WPA.
      mine_ = merge_active(keep, got, w);
      ctx.alloc(wpa_record_bytes(mine_), "merged pixels");
      ctx.release(held + gathered + received);
      held = wpa_record_bytes(mine_);
    }
  }
};

} // namespace

std::unique_ptr<MergeScheme> make_pair(const ScreenPartition& partition) {
  return std::make_unique<PairwiseExchange>(partition);
}

} // namespace zc::kurc
