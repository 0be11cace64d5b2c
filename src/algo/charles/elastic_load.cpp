// Charles, Lefevre, Miguet 1995, §4-§5: GlobalLoad = MultiReduce(LocalLoad), and the elastic cut
// of the picture rows into slices of equal estimated work that it allows.
#include <algorithm>

#include "algo/charles/elastic_steps.hpp"
#include "comm/collectives.hpp"

namespace zc::elastic {

std::vector<std::int64_t> multireduce_load(NodeContext& ctx,
                                           const std::vector<std::int64_t>& local) {
  auto ph = ctx.phase("multireduce_load");
  // A row's load (triangles crossing it) is a C int: 4 bytes an entry on the wire.
  const auto sum = coll::allreduce(
      ctx.comm(), std::vector<std::int32_t>(local.begin(), local.end()), coll::Op::Sum);
  const std::vector<std::int64_t> global(sum.begin(), sum.end());
  Counters w;
  w.rows_scanned = std::uint64_t(local.size()) * std::uint64_t(std::max(1, ctx.comm().dimension()));
  ctx.charge(w);
  return global;
}

std::vector<int> partition_rows(NodeContext& ctx, const std::vector<std::int64_t>& global_load) {
  auto ph = ctx.phase("partition");
  auto bounds = elastic_partition(global_load, ctx.nodes());
  Counters w;
  w.rows_scanned = std::uint64_t(global_load.size());
  ctx.charge(w);
  return bounds;
}

} // namespace zc::elastic
