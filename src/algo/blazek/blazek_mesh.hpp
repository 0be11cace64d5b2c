#pragma once
// Blazek 1991, ch. II "Tessellation" and ch. V: a node's polygons, tessellated from an object
// description (node initiated, object forwarding, host broadcast) or received as polygons (host
// initiated packets, forwarded polygons), and their vertices projected.
#include <cstdint>
#include <vector>

#include "algo/algorithm.hpp"
#include "algo/blazek/blazek_wire.hpp"
#include "raster/renderer.hpp"

namespace zc::blazek {

// A node's polygons, as a shared-vertex mesh: an object's tessellation keeps its shared vertices,
// so each is transformed once (as the sequential renderer does); polygons that travelled as Poly
// records (host initiated packets, forwarded polygons) bring three vertices each, which the node
// transforms one by one: the price of shipping polygons rather than descriptions.
struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<TriangleRecord> tris; // global ids; vertex numbers index `vertices`
  double bytes() const {
    return double(vertices.size() * sizeof(Vertex) + tris.size() * sizeof(TriangleRecord));
  }
};
Mesh mesh_of(const std::vector<Poly>& polys);
// Node memory a tessellation held besides its message takes: the mesh and its projected vertices.
inline double tessellation_bytes(const Mesh& m) {
  return m.bytes() + double(m.vertices.size() * sizeof(ProjectedVertex));
}
// The polygons of a subset (indices into m.tris) of a mesh, to be sent.
std::vector<Poly> polys_of(const Mesh& m, const std::vector<std::uint32_t>& subset);

// Decodes an object description message and tessellates it (charging triangles_tessellated).
Mesh object_mesh(NodeContext& ctx, const Bytes& msg);

// A mesh with its vertices projected (vertices_transformed charged once per vertex).
struct ProjectedMesh {
  const Mesh& mesh;
  std::vector<ProjectedVertex> pv;
  ProjectedMesh(NodeContext& ctx, const NodeRenderer& nr, const Mesh& m);
  // Rows [y0, y1] triangle t can touch (false: none: culled or off screen).
  bool rows(const NodeRenderer& nr, std::uint32_t t, int& y0, int& y1) const;

private:
  // What row_extent needs of each vertex, worked out on the first rows() a process's set-up cache
  // does not answer (host time only: the node is charged per triangle, as before).
  mutable std::vector<VertexExtent> extents_;
};

} // namespace zc::blazek
