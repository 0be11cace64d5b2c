#include "geometry/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace zc {

void resolve_clip_planes(const Camera& cam, const Bounds& b, double& znear, double& zfar) {
  znear = cam.znear;
  zfar = cam.zfar;
  if (znear > 0 && zfar > znear) return;
  // A scene that is a single point gets a radius; any other keeps its own, however small (a floor
  // of 1e-6 put the near plane in front of scenes below 5e-10 across: blank images).
  double r = b.radius() > 0 ? b.radius() : 1e-6;
  double d = b.empty ? 1.0 : glm::length(cam.eye - b.center());
  if (!(znear > 0)) znear = std::max((d - r) * 0.95, r * 1e-3);
  if (!(zfar > znear)) zfar = std::max(d + r, znear * 2.0) * 1.05;
}

glm::dmat4 view_matrix(const Camera& cam) {
  return glm::lookAt(cam.eye, cam.target, cam.up);
}

glm::dmat4 projection_matrix(const Camera& cam, double aspect, double znear, double zfar) {
  return glm::perspective(glm::radians(cam.fovy_deg), aspect, znear, zfar);
}

Camera framing_camera(const Bounds& b, double fovy_deg) {
  Camera c;
  c.fovy_deg = fovy_deg;
  glm::dvec3 ctr = b.empty ? glm::dvec3(0) : b.center();
  double r = b.radius() > 0 ? b.radius() : 1e-6;
  double dist = r / std::sin(glm::radians(fovy_deg) * 0.5) * 1.05;
  c.target = ctr;
  c.eye = ctr + glm::dvec3(0, 0, dist);
  c.up = {0, 1, 0};
  return c;
}

} // namespace zc
