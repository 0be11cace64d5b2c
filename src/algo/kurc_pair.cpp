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
    for (int i = 0; i < c.dimension(); ++i) {
      const int bit = 1 << i, partner = r ^ bit;
      const auto leaves = [&](int y) { return (owner[y] & bit) != (r & bit); };
      auto give = select_rows(mine_, leaves);
      auto keep = select_rows(mine_, [&](int y) { return !leaves(y); });
      Bytes out = serialize_sparse(give);
      if (fragmented(H, leaves)) w.bytes_packed += out.size();
      m.step_bytes.push_back(double(out.size()));
      auto h = c.isend(partner, kTagPair + i, std::move(out));
      Bytes in = c.recv(partner, kTagPair + i);
      h->wait();
      ActivePixels got = deserialize_sparse(in.data(), in.size(), width_, 0, H);
      ctx.alloc(double(in.size()), "receive buffer");
      m.merge_load += got.count();
      mine_ = merge_active(keep, got, w);
      ctx.release(double(in.size()));
    }
  }
};

} // namespace

std::unique_ptr<MergeScheme> make_pair(const ScreenPartition& partition) {
  return std::make_unique<PairwiseExchange>(partition);
}

} // namespace zc::kurc
