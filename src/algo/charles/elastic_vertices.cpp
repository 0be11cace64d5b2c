// Charles, Lefevre, Miguet 1995: MultiBroadcast(Projected Vertices) (§4) and the request/answer
// scheme of §7 that replaces it.
#include "algo/charles/elastic_vertices.hpp"

#include <algorithm>
#include <stdexcept>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"

namespace zc::elastic {

void BroadcastVertices::exchange(NodeContext& ctx, const LocalScene& local,
                                 const std::vector<ProjectedVertex>& mine) {
  auto ph = ctx.phase("multibroadcast_vertices");
  // Charged as the paper's projected vertices (screen point and R.G.B. colour, records.hpp).
  const Message m{pack(mine), mine.size() * records::charles::kProjectedVertex};
  blocks = coll::allgatherv(ctx.comm(), m);
  scene_vertices = local.scene_vertices;
  std::size_t received = 0;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    block.push_back(blocks[k].payload.records<ProjectedVertex>());
    if (block.back().size() != block_range(scene_vertices, int(blocks.size()), int(k)).size())
      throw std::runtime_error(
          "multibroadcast: a node's projected vertices do not match its block");
    received += block.back().size();
  }
  // Each node's projected vertices are one contiguous array, multi-broadcast in place into the
  // array of all of them (PPCM): no packing charged.
  bytes = double(received * records::charles::kProjectedVertex);
}

namespace {

// The distinct vertices of the node's triangles, listed per owning node (ascending ids).
std::vector<std::vector<std::uint32_t>> vertices_wanted(NodeContext& ctx, const LocalScene& local) {
  const int P = ctx.nodes();
  std::vector<std::uint32_t> ids;
  for (const auto& t : local.triangles)
    ids.insert(ids.end(), t.tri.v, t.tri.v + 3);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  std::vector<std::vector<std::uint32_t>> want(P);
  for (auto id : ids)
    want[block_of(local.scene_vertices, P, id)].push_back(id);
  Counters w;
  w.rows_scanned = ids.size(); // building the request lists
  ctx.charge(w);
  return want;
}

} // namespace

void RequestedVertices::exchange(NodeContext& ctx, const LocalScene& local,
                                 const std::vector<ProjectedVertex>& mine) {
  auto ph = ctx.phase("request_vertices");
  const int P = ctx.nodes();
  const auto want = vertices_wanted(ctx, local);
  std::vector<Bytes> requests(P);
  for (int k = 0; k < P; ++k)
    requests[k] = pack(want[k]);
  auto asked = coll::alltoallv(ctx.comm(), std::move(requests));
  std::vector<Message> answers(P);
  for (int k = 0; k < P; ++k) {
    std::vector<ProjectedVertex> answer;
    for (auto id : unpack<std::uint32_t>(asked[k]))
      answer.push_back(mine[id - local.first_vertex]);
    answers[k] = {pack(answer), answer.size() * records::charles::kProjectedVertex};
  }
  auto got = coll::alltoallv(ctx.comm(), std::move(answers));
  for (int k = 0; k < P; ++k) {
    auto pvs = unpack<ProjectedVertex>(got[k].payload);
    for (std::size_t i = 0; i < pvs.size(); ++i)
      known[want[k][i]] = pvs[i];
  }
  bytes = double(known.size() * (records::charles::kProjectedVertex + 4)); // + the id as key
  ctx.charge_packing(std::size_t(bytes));
}

} // namespace zc::elastic
