// renumber_vertices_by_first_use: the triangles keep their corners' positions, the vertices come
// in first-use order, unused ones go.
#include <gtest/gtest.h>

#include "scene/vertex_order.hpp"

namespace zc {
namespace {

Scene two_triangles_reversed() {
  Scene s;
  for (int i = 0; i < 6; ++i)
    s.vertices.push_back({glm::vec3(float(i), float(10 * i), 0.0f), glm::vec3(0, 0, 1)});
  // Vertex 5 first, then 0; vertex 2 is used by no triangle.
  s.triangles = {Triangle{{5, 4, 3}, 0}, Triangle{{0, 1, 3}, 0}};
  return s;
}

TEST(VertexOrder, FirstUseOrderAndSamePositions) {
  const Scene before = two_triangles_reversed();
  Scene s = before;
  renumber_vertices_by_first_use(s);
  ASSERT_EQ(s.triangles.size(), before.triangles.size());
  ASSERT_EQ(s.vertices.size(), 5u); // vertex 2 dropped
  // Corners numbered in the order they are first met: 0 1 2, then 3 4 and the shared 2.
  EXPECT_EQ(s.triangles[0].v[0], 0u);
  EXPECT_EQ(s.triangles[0].v[1], 1u);
  EXPECT_EQ(s.triangles[0].v[2], 2u);
  EXPECT_EQ(s.triangles[1].v[0], 3u);
  EXPECT_EQ(s.triangles[1].v[1], 4u);
  EXPECT_EQ(s.triangles[1].v[2], 2u);
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(s.vertices[s.triangles[t].v[k]].position,
                before.vertices[before.triangles[t].v[k]].position);
}

TEST(VertexOrder, TextureCoordinatesFollowTheirVertices) {
  Scene s = two_triangles_reversed();
  for (int i = 0; i < 6; ++i)
    s.uvs.push_back(glm::vec2(float(i), 0.0f));
  renumber_vertices_by_first_use(s);
  ASSERT_EQ(s.uvs.size(), s.vertices.size());
  for (std::size_t i = 0; i < s.vertices.size(); ++i)
    EXPECT_EQ(s.uvs[i].x, s.vertices[i].position.x); // uv i was made from vertex i's x
}

TEST(VertexOrder, RefusesAnIndexPastTheVertices) {
  Scene s = two_triangles_reversed();
  s.triangles[1].v[2] = 6;
  EXPECT_THROW(renumber_vertices_by_first_use(s), std::logic_error);
}

} // namespace
} // namespace zc
