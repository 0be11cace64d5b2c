#include "raster/view.hpp"

#include <algorithm>

#include "geometry/camera.hpp"

namespace zc {

ProjectedVertex View::project(const Vertex& v) const {
  const glm::dvec4 c = view_proj * glm::dvec4(glm::dvec3(v.position), 1.0);
  ProjectedVertex p;
  p.clip[0] = static_cast<float>(c.x);
  p.clip[1] = static_cast<float>(c.y);
  p.clip[2] = static_cast<float>(c.z);
  p.clip[3] = static_cast<float>(c.w);
  glm::vec3 l = ambient;
  for (std::size_t i = 0; i < light_dirs.size(); ++i)
    l += light_colors[i] * std::max(0.0f, glm::dot(v.normal, light_dirs[i]));
  p.light[0] = l.x;
  p.light[1] = l.y;
  p.light[2] = l.z;
  return p;
}

View make_view(const Scene& scene) {
  return make_view(scene, scene.camera);
}

View make_view(const Scene& scene, const Camera& camera) {
  return make_view(scene, camera, scene_bounds(scene));
}

View make_view(const Scene& scene, const Camera& camera, const Bounds& bounds) {
  View v;
  v.width = scene.width;
  v.height = scene.height;
  resolve_clip_planes(camera, bounds, v.znear, v.zfar);
  const double aspect = static_cast<double>(scene.width) / std::max(1, scene.height);
  v.view_proj = projection_matrix(camera, aspect, v.znear, v.zfar) * view_matrix(camera);
  v.ambient = scene.ambient;
  for (const auto& l : scene.lights) {
    const float len = glm::length(l.direction);
    v.light_dirs.push_back(len > 0 ? -l.direction / len : glm::vec3(0, 0, 1));
    v.light_colors.push_back(l.color);
  }
  return v;
}

} // namespace zc
