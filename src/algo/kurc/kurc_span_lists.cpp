// Kurc, Aykanat, Ozguc: distribution of the triangles and span list creation (§2, first step),
// shared by every merge scheme.
#include "algo/kurc/kurc_span_lists.hpp"

#include <unordered_map>

#include "algo/composite.hpp"
#include "algo/records.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "compositing/winning_pixels.hpp"

namespace zc::kurc {

namespace {
// Scene triangle i as a node holds it: its world polygon, vertex ids and (textured) coordinates.
void add_triangle(NodeTriangles& to, const Scene& scene, std::size_t i) {
  const Triangle& t = scene.triangles[i];
  to.tris.push_back({world_polygon(scene, std::uint32_t(i)), {t.v[0], t.v[1], t.v[2]}});
  if (scene.textured())
    to.uvs.push_back({{scene.uvs[t.v[0]], scene.uvs[t.v[1]], scene.uvs[t.v[2]]}});
}
} // namespace

NodeTriangles all_triangles(const Scene& scene) {
  NodeTriangles all;
  for (std::size_t i = 0; i < scene.triangles.size(); ++i)
    add_triangle(all, scene, i);
  return all;
}

NodeTriangles distribute_triangles(NodeContext& ctx) {
  auto ph = ctx.phase("distribute");
  const Scene& scene = ctx.scene();
  const int P = ctx.nodes();
  const bool textured = scene.textured();
  // Node 0's blocks, one a node; the other nodes hold none (a block list each would be P^2
  // entries: 48 MB allocated and cleared over a 1024-node run).
  std::vector<Message> parts;
  std::vector<Bytes> uv_parts;
  if (ctx.rank() == 0) {
    parts.resize(std::size_t(P));
    if (textured) uv_parts.resize(std::size_t(P));
    std::vector<NodeTriangles> per(P);
    for (std::size_t i = 0; i < scene.triangles.size(); ++i)
      add_triangle(per[i % P], scene, i);
    // Each polygon is charged as the paper's record (records.hpp), not zcube's TriWorld.
    for (int k = 0; k < P; ++k) {
      parts[k] = {pack(per[k].tris), per[k].tris.size() * records::kurc::kPolygon};
      if (textured) uv_parts[k] = pack(per[k].uvs);
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
    // The triangle's own three texture coordinates travelled with it (TriUV): vertices 0, 1, 2.
    nr.setup_projected(t.poly.id, Triangle{{0, 1, 2}, t.poly.material}, p,
                       textured ? mine.uvs[i].uv : nullptr, s.batch, w);
  }
  ctx.alloc(double(s.batch.tris.size() * sizeof(ScreenTriangle)), "set-up records");
  ctx.release(projected);
  s.lists = build_span_lists(s.batch, nr.width(), nr.height(), w);
  ctx.charge(w);
  ctx.alloc(double(s.lists.bytes()), "span lists");
  return s;
}

ActivePixels scanline_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans,
                              Counters& w) {
  ctx.alloc(double(nr.width()) * 4, "MSA");
  ActivePixels wpa = zbuffer_spans(spans.lists, spans.batch, nr.shade(), nr.width(), w);
  ctx.alloc(compositing::held_bytes(wpa, kurc_pixel_records()), "WPA");
  return wpa;
}

} // namespace zc::kurc
