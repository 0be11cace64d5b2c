// Kurc, Aykanat, Ozguc: the merge schemes on the compositing layer (kurc_merge_scheme.hpp).
#include "algo/kurc/kurc_merge_scheme.hpp"

#include <algorithm>

#include "algo/composite.hpp"
#include "comm/collectives.hpp"
#include "compositing/dense.hpp"
#include "compositing/winning_pixels.hpp"

namespace zc::kurc {

void MergeScheme::local_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans,
                                Counters& w) {
  height_ = nr.height();
  if (!partition_) {
    picture_ = compositing::dense(full_zbuffer(ctx, nr, spans, w), kurc_pixel_records());
    return;
  }
  ActivePixels wpa = scanline_zbuffer(ctx, nr, spans, w);
  row_pixels_.resize(std::size_t(height_));
  for (int y = 0; y < height_; ++y)
    row_pixels_[std::size_t(y)] = std::int32_t(wpa.row_count(y));
  picture_ = compositing::winning_pixels(std::move(wpa), kurc_pixel_records());
}

// §4.1: per-scanline counts of local foremost pixels, summed over the machine (a C int each on
// the wire), then shared out.
std::vector<int> MergeScheme::share_scanlines(NodeContext& ctx, Counters& w) const {
  const auto global = coll::allreduce(ctx.comm(), row_pixels_, coll::Op::Sum);
  const std::vector<std::uint64_t> rows(global.begin(), global.end());
  w.rows_scanned = std::uint64_t(height_) * std::uint64_t(std::max(1, ctx.comm().dimension()) + 1);
  return partition_->owners(rows, ctx.nodes());
}

MergeMeasures MergeScheme::merge(NodeContext& ctx, Counters& w) {
  const std::vector<int> owner =
      partition_ ? share_scanlines(ctx, w) : even_split(height_, ctx.nodes());
  return composite(ctx, strategy_, *picture_, owner, w);
}

std::unique_ptr<MergeScheme> make_zbuf_exc() {
  return std::make_unique<MergeScheme>("zbuf-exc", compositing::binary_swap(), nullptr);
}

std::unique_ptr<MergeScheme> make_pair(const ScreenPartition& partition) {
  return std::make_unique<MergeScheme>("pair", compositing::binary_swap(), &partition);
}

std::unique_ptr<MergeScheme> make_aapc(const ScreenPartition& partition) {
  return std::make_unique<MergeScheme>("aapc", compositing::direct_send(), &partition);
}

} // namespace zc::kurc
