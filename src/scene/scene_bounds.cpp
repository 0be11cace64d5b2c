#include "scene/scene.hpp"

namespace zc {

Bounds scene_bounds(const Scene& s) {
  Bounds b;
  for (const auto& v : s.vertices)
    b.add(glm::dvec3(v.position));
  return b;
}

SceneFacts scene_facts(const Scene& s) {
  SceneFacts f;
  f.bounds = scene_bounds(s);
  for (const Triangle& t : s.triangles)
    if (t.material != s.triangles.front().material) {
      f.several_materials = true;
      break;
    }
  return f;
}

} // namespace zc
