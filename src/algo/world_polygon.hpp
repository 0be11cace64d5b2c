#pragma once
// The one polygon record that travels between nodes with its WORLD-space vertices (Blazek's
// polygon packets and forwarded polygons, Kurc et al.'s triangles dealt to the nodes): its global
// scene id (the depth tie-break), material and three vertices with normals, 80 bytes of payload
// (the network is charged each paper's polygon record, records.hpp). The receiving node projects
// and shades them.
#include <cstdint>

#include "scene/scene.hpp"

namespace zc {

struct WorldPolygon {
  std::uint32_t id, material;
  Vertex v[3];
};

// Scene triangle `id` as such a record.
inline WorldPolygon world_polygon(const Scene& s, std::uint32_t id) {
  const Triangle& t = s.triangles[id];
  return {id, t.material, {s.vertices[t.v[0]], s.vertices[t.v[1]], s.vertices[t.v[2]]}};
}

} // namespace zc
