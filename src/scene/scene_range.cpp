#include "scene/scene_range.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "util/error.hpp"

namespace zc {
namespace {

std::string show(const glm::dvec3& v) {
  char b[96];
  std::snprintf(b, sizeof b, "(%.9g, %.9g, %.9g)", v.x, v.y, v.z);
  return b;
}

std::string show(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

bool within(const glm::dvec3& v) {
  return std::fabs(v.x) <= kMaxCoordinate && std::fabs(v.y) <= kMaxCoordinate &&
         std::fabs(v.z) <= kMaxCoordinate; // false for NaN
}

const char* kCoordRange = "outside the renderer's coordinate range |x|, |y|, |z| <= 2^64 "
                          "(1.8e19, scenes/README.md 'Numeric range')";

void fail(const Scene& s, const std::string& field, const std::string& why) {
  throw InputError(s.path, 0, field + ": " + why);
}

// The object a vertex belongs to, for the message ("" when none is recorded).
std::string owner(const Scene& s, std::size_t vertex) {
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const ObjectDesc& o = s.objects[i];
    if (vertex >= o.first_vertex && vertex < std::size_t(o.first_vertex) + o.vertex_count)
      return " of object " + std::to_string(i) + " (" + o.kind + ")";
  }
  return "";
}

void check_camera(const Scene& s) {
  const Camera& c = s.camera;
  const std::pair<const char*, glm::dvec3> points[] = {
      {"camera.eye", c.eye}, {"camera.target", c.target}, {"camera.up", c.up}};
  for (const auto& [name, p] : points)
    if (!within(p)) fail(s, name, show(p) + " " + kCoordRange);
  if (!(glm::length(c.target - c.eye) >= kMinExtent))
    fail(s, "camera",
         "eye and target closer than 2^-64 (5.4e-20), the smallest extent the "
         "renderer handles (scenes/README.md 'Numeric range')");
  if (!(glm::length(c.up) >= kMinExtent))
    fail(s, "camera.up", "shorter than 2^-64 (5.4e-20), the smallest extent the renderer handles");
  if (!(c.fovy_deg >= kMinFovDeg && c.fovy_deg < 180))
    fail(s, "camera.fov",
         show(c.fovy_deg) + " degrees outside 1e-9..180 (below 1e-9 degrees the "
                            "projection overflows the renderer's float clip space)");
  for (const auto& [name, v] : {std::pair{"camera.near", c.znear}, std::pair{"camera.far", c.zfar}})
    if (!(v <= kMaxCoordinate)) fail(s, name, "beyond 2^64 (1.8e19), " + std::string(kCoordRange));
}

} // namespace

void check_numeric_range(const Scene& s) {
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    const glm::dvec3 p(s.vertices[i].position);
    if (!within(p))
      fail(s, "vertex " + std::to_string(i) + owner(s, i), show(p) + " " + kCoordRange);
  }
  check_camera(s); // after the vertices: a default camera frames them
  const Bounds b = scene_bounds(s);
  const double r = b.radius();
  if (r > 0 && !(r >= kMinExtent))
    fail(s, "objects",
         "the scene's bounding radius " + show(r) +
             " is below 2^-64 (5.4e-20), the smallest extent the renderer handles");
}

} // namespace zc
