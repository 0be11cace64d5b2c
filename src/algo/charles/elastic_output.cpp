// Charles, Lefevre, Miguet 1995, §4 "Output the picture", and Table 1 (per node triangles rendered,
// workload and rows) of the last picture.
#include <algorithm>

#include <nlohmann/json.hpp>

#include "algo/charles/elastic_steps.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "compositing/gather.hpp"
#include "util/load_imbalance.hpp"

namespace zc::elastic {

namespace {

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
  ctx.metrics()["load_imbalance"] = load_imbalance(loads);
}

} // namespace

void output_picture(NodeContext& ctx, Framebuffer slice,
                    const std::vector<std::int64_t>& global_load, const SliceOutput& out) {
  auto ph = ctx.phase("output");
  // --output gather: the slice's colours (one contiguous array, sent in place) go to node 0, which
  // displays them; the picture and its depth map are the slices themselves, handed over once sent
  // (node 0's colours are theirs, byte for byte).
  if (out.gather)
    (void)compositing::gather(ctx.comm(), 0,
                              charged_as_payload(Bytes(slice.rgb().begin(), slice.rgb().end())));
  const RowSet rows = slice.rows();
  std::int64_t work = 0;
  for (int y = rows.begin; y < rows.end; ++y)
    work += global_load[y];
  const std::vector<std::int64_t> mine{std::int64_t(out.triangles), work, rows.count()};
  auto stats = coll::gatherv(ctx.comm(), 0, pack(mine));
  ctx.deliver_rows(out.frame, std::move(slice));
  if (ctx.rank() == 0 && out.last_frame)
    record_slice_table(ctx, stats, global_load, out.scene_triangles);
}

} // namespace zc::elastic
