// Blazek 1991, ch. II "Tessellation": a node's polygons as a shared-vertex mesh, tessellated from
// an object description or made of received polygons, and projected (blazek_mesh.hpp).
#include "algo/blazek/blazek_mesh.hpp"

#include <stdexcept>

#include "comm/wire.hpp"
#include "scene/tessellate.hpp"

namespace zc::blazek {

Mesh mesh_of(const std::vector<Poly>& polys) {
  Mesh m;
  m.vertices.reserve(3 * polys.size());
  m.tris.reserve(polys.size());
  for (const Poly& p : polys) {
    const auto at = std::uint32_t(m.vertices.size());
    m.tris.push_back({p.id, {{at, at + 1, at + 2}, p.material}});
    m.vertices.insert(m.vertices.end(), p.v, p.v + 3);
  }
  return m;
}

std::vector<Poly> polys_of(const Mesh& m, const std::vector<std::uint32_t>& subset) {
  std::vector<Poly> out;
  out.reserve(subset.size());
  for (std::uint32_t t : subset) {
    const TriangleRecord& tr = m.tris[t];
    const Triangle& t3 = tr.tri;
    out.push_back(
        {tr.id, t3.material, {m.vertices[t3.v[0]], m.vertices[t3.v[1]], m.vertices[t3.v[2]]}});
  }
  return out;
}

Mesh object_mesh(NodeContext& ctx, const Bytes& msg) {
  const auto got = decode_object(msg);
  if (!got) throw std::runtime_error("object message too short");
  const ObjectHeader& h = got->header;
  if (h.is_mesh) return mesh_of(unpack<Poly>(got->rest, got->rest_size));
  ObjectDesc d;
  d.first_vertex = h.first_vertex;
  d.vertex_count = h.vertex_count;
  d.first_triangle = h.first_triangle;
  d.triangle_count = h.triangle_count;
  d.text.assign(reinterpret_cast<const char*>(got->rest), got->rest_size);
  Tessellation t = tessellate(d);
  Mesh m;
  m.vertices = std::move(t.vertices);
  m.tris.reserve(t.triangles.size());
  for (std::size_t i = 0; i < t.triangles.size(); ++i) {
    const Triangle& tr = t.triangles[i];
    m.tris.push_back(
        {d.first_triangle + std::uint32_t(i),
         {{tr.v[0] - d.first_vertex, tr.v[1] - d.first_vertex, tr.v[2] - d.first_vertex},
          tr.material}});
  }
  Counters c;
  c.triangles_tessellated = m.tris.size();
  ctx.charge(c);
  return m;
}

ProjectedMesh::ProjectedMesh(NodeContext& ctx, const NodeRenderer& nr, const Mesh& m) : mesh(m) {
  Counters c;
  pv.reserve(m.vertices.size());
  for (const Vertex& v : m.vertices)
    pv.push_back(nr.project(v, c));
  ctx.charge(c);
}

bool ProjectedMesh::rows(const NodeRenderer& nr, std::uint32_t t, int& y0, int& y1) const {
  const Triangle& tr = mesh.tris[t].tri;
  const ProjectedVertex* pp[3] = {&pv[tr.v[0]], &pv[tr.v[1]], &pv[tr.v[2]]};
  if (nr.has_setup_cache()) return nr.rows(mesh.tris[t].id, pp, y0, y1);
  if (extents_.size() != pv.size()) {
    extents_.resize(pv.size());
    for (std::size_t i = 0; i < pv.size(); ++i)
      extents_[i] = vertex_extent(pv[i], nr.height());
  }
  const VertexExtent* ep[3] = {&extents_[tr.v[0]], &extents_[tr.v[1]], &extents_[tr.v[2]]};
  return row_extent(pp, ep, nr.height(), y0, y1);
}

} // namespace zc::blazek
