#include "scene/vertex_order.hpp"

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace zc {

void renumber_vertices_by_first_use(Scene& s) {
  constexpr std::uint32_t kUnset = 0xffffffffu;
  const bool with_uvs = !s.uvs.empty();
  if (with_uvs && s.uvs.size() != s.vertices.size())
    throw std::logic_error("renumber_vertices_by_first_use: one texture coordinate a vertex");
  std::vector<std::uint32_t> to(s.vertices.size(), kUnset);
  std::vector<Vertex> vertices;
  std::vector<glm::vec2> uvs;
  vertices.reserve(s.vertices.size());
  for (Triangle& t : s.triangles)
    for (std::uint32_t& v : t.v) {
      if (v >= to.size()) throw std::logic_error("renumber_vertices_by_first_use: bad index");
      if (to[v] == kUnset) {
        to[v] = std::uint32_t(vertices.size());
        vertices.push_back(s.vertices[v]);
        if (with_uvs) uvs.push_back(s.uvs[v]);
      }
      v = to[v];
    }
  s.vertices = std::move(vertices);
  if (with_uvs) s.uvs = std::move(uvs);
}

} // namespace zc
