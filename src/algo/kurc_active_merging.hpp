#pragma once
// Kurc, Aykanat, Ozguc: what the two active pixel merging schemes (PAIR, AAPC) share. The local
// z-buffer is the modified scanline z-buffer into the Winning Pixel Array (§2), and before the
// exchange the scanlines are shared among the nodes by the machine-wide active pixel counts (§4).
#include "algo/kurc_merge_scheme.hpp"

namespace zc::kurc {

class ActivePixelMerging : public MergeScheme {
public:
  explicit ActivePixelMerging(const ScreenPartition& partition) : partition_(partition) {}
  void local_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans,
                     Counters& w) override;
  MergeMeasures merge(NodeContext& ctx, Counters& w) override;
  ActivePixels final_pixels(Counters&) override { return std::move(mine_); }

protected:
  // The scheme's exchange: from wpa_ (the local foremost pixels) to mine_ (the final pixels of the
  // scanlines with owner[y] == this node).
  virtual void exchange(NodeContext& ctx, const std::vector<int>& owner, MergeMeasures& m,
                        Counters& w) = 0;

  ActivePixels wpa_, mine_;
  int width_ = 0; // of the screen

private:
  std::vector<int> share_scanlines(NodeContext& ctx, Counters& w) const;

  ScreenPartition partition_;
};

// True when the rows y in [0, h) with in(y) form more than one run: such a message has to be
// gathered from several places of the WPA (a copy); one run is sent in place. Packing is charged
// only for such messages: the local foremost pixels are stored in consecutive memory locations
// precisely so that a message over one run is a contiguous region, sent and merged in place (§2),
// as a full z-buffer's half is. zcube's own copies into Bytes are an artefact of its wire format.
template <class Pred> bool fragmented(int h, Pred in) {
  int runs = 0;
  for (int y = 0; y < h; ++y)
    runs += in(y) && (y == 0 || !in(y - 1));
  return runs > 1;
}

} // namespace zc::kurc
