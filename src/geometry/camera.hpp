#pragma once
// Camera matrices (double precision, OpenGL conventions: right-handed eye space looking down -z,
// clip-space depth in [-w, w]).
#include <glm/glm.hpp>

namespace zc {

// A viewer: position, aim, up direction and lens.
struct Camera {
  glm::dvec3 eye{0, 0, 5};
  glm::dvec3 target{0, 0, 0};
  glm::dvec3 up{0, 1, 0};
  double fovy_deg = 45.0; // vertical field of view
  double znear = 0;       // 0 = derived from the scene's bounds
  double zfar = 0;        // 0 = derived from the scene's bounds
};

struct Bounds {
  glm::dvec3 lo{0}, hi{0};
  bool empty = true;
  // Inline: scene_bounds calls it once per vertex of the scene.
  void add(const glm::dvec3& p) {
    if (empty) {
      lo = hi = p;
      empty = false;
    } else {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  glm::dvec3 center() const { return (lo + hi) * 0.5; }
  double radius() const { return empty ? 0.0 : glm::length(hi - lo) * 0.5; }
};

// Near/far planes: the camera's if set, else fitted around the scene's bounding sphere.
void resolve_clip_planes(const Camera& cam, const Bounds& b, double& znear, double& zfar);

glm::dmat4 view_matrix(const Camera& cam);
glm::dmat4 projection_matrix(const Camera& cam, double aspect, double znear, double zfar);

// A camera that frames the bounds (used for a bare mesh): looking down -z at the centre.
Camera framing_camera(const Bounds& b, double fovy_deg = 40.0);

} // namespace zc
