#include "geometry/camera_path.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace zc {

Camera camera_at_frame(const Camera& base, int frame, int frames) {
  if (frames <= 1 || frame == 0) return base;
  const double t = double(frame) / double(frames);
  const double angle = 2.0 * M_PI * t;
  const double zoom = 1.0 - 0.15 * (1.0 - std::cos(angle)); // 1 at t = 0, 0.7 at t = 1/2
  const glm::dvec3 axis = glm::normalize(base.up);
  const glm::dmat4 rot = glm::rotate(glm::dmat4(1.0), angle, axis);
  const glm::dvec3 offset = glm::dvec3(rot * glm::dvec4(base.eye - base.target, 0.0));
  Camera c = base;
  c.eye = base.target + offset * zoom;
  return c;
}

} // namespace zc
