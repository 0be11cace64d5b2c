// Kurc, Aykanat, Ozguc: distribution of the triangles and span list creation (§2, first step),
// shared by every merge scheme.
#include "algo/kurc_span_lists.hpp"

#include <unordered_map>

#include "algo/records.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"

namespace zc::kurc {

NodeTriangles distribute_triangles(NodeContext& ctx) {
  auto ph = ctx.phase("distribute");
  const Scene& scene = ctx.scene();
  const int P = ctx.nodes();
  const bool textured = scene.textured();
  std::vector<Message> parts(P);
  std::vector<Bytes> uv_parts(P);
  if (ctx.rank() == 0) {
    std::vector<std::vector<TriWorld>> per(P);
    std::vector<std::vector<TriUV>> per_uv(P);
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
      const Triangle& t = scene.triangles[i];
      per[i % P].push_back({world_polygon(scene, std::uint32_t(i)), {t.v[0], t.v[1], t.v[2]}});
      if (textured)
        per_uv[i % P].push_back({{scene.uvs[t.v[0]], scene.uvs[t.v[1]], scene.uvs[t.v[2]]}});
    }
    // Each polygon is charged as the paper's record (records.hpp), not zcube's TriWorld.
    for (int k = 0; k < P; ++k) {
      parts[k] = {pack(per[k]), per[k].size() * records::kurc::kPolygon};
      if (textured) uv_parts[k] = pack(per_uv[k]);
    }
    ctx.charge_packing(scene.triangles.size() * records::kurc::kPolygon);
  }
  NodeTriangles mine;
  mine.tris = unpack<TriWorld>(coll::scatterv(ctx.comm(), 0, std::move(parts)).payload);
  if (textured) mine.uvs = unpack<TriUV>(coll::scatterv(ctx.comm(), 0, std::move(uv_parts)));
  ctx.alloc(double(mine.tris.size() * records::kurc::kPolygon + mine.uvs.size() * sizeof(TriUV)),
            "triangles");
  return mine;
}

NodeSpans create_span_lists(NodeContext& ctx, const NodeRenderer& nr, const NodeTriangles& mine) {
  auto ph = ctx.phase("span_list_creation");
  const bool textured = ctx.scene().textured();
  Counters w;
  std::unordered_map<std::uint32_t, ProjectedVertex> pv;
  for (const auto& t : mine.tris)
    for (int k = 0; k < 3; ++k)
      if (!pv.count(t.vid[k])) pv.emplace(t.vid[k], nr.project(t.poly.v[k], w));
  // The projected vertices are held until every triangle is set up (28 bytes each).
  const double projected = double(pv.size() * sizeof(ProjectedVertex));
  ctx.alloc(projected, "projected vertices");
  NodeSpans s;
  for (std::size_t i = 0; i < mine.tris.size(); ++i) {
    const TriWorld& t = mine.tris[i];
    const ProjectedVertex* p[3] = {&pv[t.vid[0]], &pv[t.vid[1]], &pv[t.vid[2]]};
    const glm::vec2* uv[3] = {nullptr, nullptr, nullptr};
    if (textured)
      for (int k = 0; k < 3; ++k)
        uv[k] = &mine.uvs[i].uv[k];
    nr.setup(t.poly.id, Triangle{{t.vid[0], t.vid[1], t.vid[2]}, t.poly.material}, p,
             textured ? uv : nullptr, s.batch, w);
  }
  ctx.alloc(double(s.batch.tris.size() * sizeof(ScreenTriangle)), "set-up records");
  ctx.release(projected);
  s.lists = build_span_lists(s.batch, nr.width(), nr.height(), w);
  ctx.charge(w);
  ctx.alloc(double(s.lists.bytes()), "span lists");
  return s;
}

} // namespace zc::kurc
