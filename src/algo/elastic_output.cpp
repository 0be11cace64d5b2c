// Charles, Lefevre, Miguet 1995, §4 "Output the picture", and Table 1 (per node triangles rendered,
// workload and rows) of the last picture.
#include <algorithm>

#include "algo/elastic_steps.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"

namespace zc::elastic {

namespace {

// Node 0's full picture from the slices' colours (--output gather).
Framebuffer assemble_picture(const NodeRenderer& nr, const std::vector<Bytes>& slices,
                             const std::vector<int>& bounds) {
  Framebuffer full = nr.make_framebuffer(RowSet::all(nr.height()));
  for (std::size_t k = 0; k < slices.size(); ++k)
    std::copy(slices[k].begin(), slices[k].end(),
              full.rgb().begin() + std::ptrdiff_t(3) * bounds[k] * nr.width());
  // Each slice lands in its own rows of the picture (received in place): no packing charged.
  return full;
}

// Table 1 from every node's {triangles, workload, rows}, into node 0's report metrics.
void record_slice_table(NodeContext& ctx, const std::vector<Bytes>& stats,
                        const std::vector<std::int64_t>& global_load, std::size_t scene_triangles) {
  std::int64_t total = 0;
  for (auto load : global_load)
    total += load;
  auto table = nlohmann::json::array();
  std::uint64_t sum_tris = 0;
  std::vector<std::uint64_t> loads;
  for (std::size_t k = 0; k < stats.size(); ++k) {
    auto s = unpack<std::int64_t>(stats[k]);
    sum_tris += std::uint64_t(s[0]);
    loads.push_back(std::uint64_t(s[1]));
    table.push_back({{"node", k},
                     {"triangles", s[0]},
                     {"workload", s[1]},
                     {"work_percent", total ? 100.0 * double(s[1]) / double(total) : 0.0},
                     {"rows", s[2]}});
  }
  ctx.metrics()["elastic"] = {
      {"slices", table},
      {"triangles_rendered", sum_tris},
      {"duplicated_triangles", std::int64_t(sum_tris) - std::int64_t(scene_triangles)},
      {"vertices", ctx.options().get("vertices")},
      {"max_row_load", *std::max_element(global_load.begin(), global_load.end())}};
  const auto [mn, mx] = std::minmax_element(loads.begin(), loads.end());
  ctx.metrics()["load_imbalance"] = total ? double(*mx - *mn) / (double(total) / ctx.nodes()) : 0.0;
}

} // namespace

void output_picture(NodeContext& ctx, const NodeRenderer& nr, Framebuffer slice,
                    const std::vector<int>& bounds, const std::vector<std::int64_t>& global_load,
                    const SliceOutput& out) {
  auto ph = ctx.phase("output");
  std::vector<Bytes> slices;
  if (out.gather) {
    // The slice's colours are one contiguous array, sent in place.
    slices = coll::gatherv(ctx.comm(), 0, slice.rgb());
  }
  const RowSet rows = slice.rows();
  std::int64_t work = 0;
  for (int y = rows.begin; y < rows.end; ++y)
    work += global_load[y];
  const std::vector<std::int64_t> mine{std::int64_t(out.triangles), work, rows.count()};
  auto stats = coll::gatherv(ctx.comm(), 0, pack(mine));
  if (!out.gather) ctx.deliver_rows(out.frame, std::move(slice));
  if (ctx.rank() != 0) return;
  Framebuffer full;
  if (out.gather) full = assemble_picture(nr, slices, bounds);
  if (out.last_frame) record_slice_table(ctx, stats, global_load, out.scene_triangles);
  if (out.gather) ctx.deliver_image(out.frame, std::move(full));
}

} // namespace zc::elastic
