// Kurc, Aykanat, Ozguc: the local z-buffer and screen sharing common to PAIR and AAPC.
#include "algo/kurc_active_merging.hpp"

#include <algorithm>
#include <cstring>

#include "comm/collectives.hpp"

namespace zc::kurc {

void ActivePixelMerging::local_zbuffer(NodeContext& ctx, const NodeRenderer& nr,
                                       const NodeSpans& spans, Counters& w) {
  const int W = width_ = nr.width();
  ctx.alloc(double(W) * 4, "MSA");
  wpa_ = zbuffer_spans(spans.lists, spans.batch, nr.shade(), W, w);
  ctx.alloc(wpa_record_bytes(wpa_), "WPA");
}

Message sparse_message(Bytes payload) {
  std::uint32_t rows = 0;
  if (payload.size() >= sizeof rows) std::memcpy(&rows, payload.data(), sizeof rows);
  const std::size_t header = 4 + 8 * std::size_t(rows);
  const std::size_t pixels = (payload.size() - std::min(header, payload.size())) / kWirePixelBytes;
  const std::size_t charged = header + pixels * records::kurc::kWinningPixel;
  return {std::move(payload), charged};
}

// §4.1: per-scanline counts of local foremost pixels, summed over the machine, then shared out.
std::vector<int> ActivePixelMerging::share_scanlines(NodeContext& ctx, Counters& w) const {
  const int H = wpa_.y1 - wpa_.y0;
  std::vector<std::int64_t> counts(H);
  for (int y = 0; y < H; ++y)
    counts[y] = wpa_.row_count(y);
  // A scanline's count is a C int: 4 bytes an entry on the wire.
  const auto global = coll::allreduce(
      ctx.comm(), std::vector<std::int32_t>(counts.begin(), counts.end()), coll::Op::Sum);
  const std::vector<std::uint64_t> rows(global.begin(), global.end());
  w.rows_scanned = std::uint64_t(H) * std::uint64_t(std::max(1, ctx.comm().dimension()) + 1);
  return partition_.owners(rows, ctx.nodes());
}

MergeMeasures ActivePixelMerging::merge(NodeContext& ctx, Counters& w) {
  const std::vector<int> owner = share_scanlines(ctx, w);
  MergeMeasures m;
  exchange(ctx, owner, m, w);
  return m;
}

} // namespace zc::kurc
