#include "scene/scene.hpp"

namespace zc {

Bounds scene_bounds(const Scene& s) {
  Bounds b;
  for (const auto& v : s.vertices)
    b.add(glm::dvec3(v.position));
  return b;
}

} // namespace zc
