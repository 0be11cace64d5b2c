#pragma once
// Vertex stage: everything needed to turn a world-space vertex into a projected, lit vertex
// (Charles et al. §4 "Project vertices": one matrix-vector product, and the Gouraud vertex colour
// from the cosine between the normal and each light).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace zc {

// A projected vertex as it travels between nodes: clip-space position and the light reaching the
// vertex (the material colour is applied per triangle). Trivially copyable, 28 bytes.
struct ProjectedVertex {
  float clip[4];
  float light[3];
};
static_assert(sizeof(ProjectedVertex) == 28);

struct View {
  int width = 0, height = 0;
  double znear = 0, zfar = 0;
  glm::dmat4 view_proj{1.0};
  glm::vec3 ambient{0};
  std::vector<glm::vec3> light_dirs; // unit vectors from the surface towards each light
  std::vector<glm::vec3> light_colors;

  ProjectedVertex project(const Vertex& v) const;
};

// Builds the view of a scene (resolving near/far from its bounds when the camera leaves them 0).
View make_view(const Scene& scene);
// The same with another camera (frames of an animation).
View make_view(const Scene& scene, const Camera& camera);
// The same with the scene's bounds already known (scene_bounds).
View make_view(const Scene& scene, const Camera& camera, const Bounds& bounds);

} // namespace zc
