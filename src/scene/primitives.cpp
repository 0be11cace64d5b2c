#include "scene/primitives.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <utility>

namespace zc {

namespace {

void tri(LocalMesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  Triangle t;
  t.v[0] = a;
  t.v[1] = b;
  t.v[2] = c;
  m.triangles.push_back(t);
}

std::uint32_t vert(LocalMesh& m, const glm::dvec3& p, const glm::dvec3& n) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  return std::uint32_t(m.positions.size() - 1);
}

} // namespace

// Blazek ch. II: "take a regular octahedron having each of its eight points lying on the unit
// sphere. Replace each of the eight triangular polygons ... by four smaller polygons, while
// maintaining all new vertices on the unit sphere." Edge midpoints are shared through a map keyed
// by the (ordered) vertex pair, and normalize(a + b) is symmetric in a and b, so neighbouring faces
// meet exactly (no cracks).
static LocalMesh build_sphere(int recursion) {
  LocalMesh m;
  const glm::dvec3 oct[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const auto& p : oct)
    vert(m, p, p);
  // Eight faces, counter-clockwise seen from outside.
  const int faces[8][3] = {{0, 2, 4}, {4, 2, 1}, {1, 2, 5}, {5, 2, 0},
                           {4, 3, 0}, {1, 3, 4}, {5, 3, 1}, {0, 3, 5}};
  for (const auto& f : faces)
    tri(m, std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2]));
  for (int level = 0; level < recursion; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      glm::dvec3 p = glm::normalize(m.positions[a] + m.positions[b]);
      std::uint32_t i = vert(m, p, p);
      mid.emplace(key, i);
      return i;
    };
    std::vector<Triangle> old;
    old.swap(m.triangles);
    m.triangles.reserve(old.size() * 4);
    for (const auto& t : old) {
      std::uint32_t a = t.v[0], b = t.v[1], c = t.v[2];
      std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      tri(m, a, ab, ca);
      tri(m, ab, b, bc);
      tri(m, ca, bc, c);
      tri(m, ab, bc, ca);
    }
  }
  return m;
}

// The unit sphere of each recursion level is built once a process and copied: Blazek's nodes
// tessellate every sphere they receive, and a scene of N spheres asks for the same mesh N times.
// (A kept mesh is never erased: references to it stay valid as other levels are added.)
const LocalMesh& sphere_mesh(int recursion, LocalMesh& built) {
  constexpr int kKept = 6; // deeper levels (4^7 * 8 triangles and more) are built each time
  if (recursion < 0 || recursion > kKept) return built = build_sphere(recursion);
  static std::mutex lock;
  static std::map<int, LocalMesh> kept;
  const std::lock_guard<std::mutex> hold(lock);
  auto it = kept.find(recursion);
  if (it == kept.end()) it = kept.emplace(recursion, build_sphere(recursion)).first;
  return it->second;
}

LocalMesh make_sphere(int recursion) {
  LocalMesh built;
  const LocalMesh& m = sphere_mesh(recursion, built);
  return &m == &built ? built : m;
}

LocalMesh make_spheroid(int recursion, const glm::dvec3& radii) {
  LocalMesh m = make_sphere(recursion);
  const glm::dvec3 inv2 = 1.0 / (radii * radii);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    glm::dvec3 p = m.positions[i] * radii;
    m.positions[i] = p;
    m.normals[i] = glm::normalize(p * inv2); // gradient of x²/a² + y²/b² + z²/c²
  }
  return m;
}

LocalMesh make_cube() {
  LocalMesh m;
  // For each face: normal, and two axes u, v with u x v = normal (so the quad is CCW from outside).
  const glm::dvec3 n[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const auto& nn : n) {
    glm::dvec3 u = std::abs(nn.y) > 0 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    glm::dvec3 v = glm::cross(nn, u);
    std::uint32_t a = vert(m, nn - u - v, nn);
    std::uint32_t b = vert(m, nn + u - v, nn);
    std::uint32_t c = vert(m, nn + u + v, nn);
    std::uint32_t d = vert(m, nn - u + v, nn);
    // v = n x u, so u x v = n and a -> b -> c runs counter-clockwise around n.
    tri(m, a, b, c);
    tri(m, a, c, d);
  }
  return m;
}

namespace {
// Angle k of `slices` around the y axis; points go counter-clockwise seen from +y.
glm::dvec2 ring(int k, int slices) {
  const double a = 2.0 * std::numbers::pi * double(k % slices) / double(slices);
  return {std::cos(a), -std::sin(a)};
}
} // namespace

LocalMesh make_cylinder(int slices) {
  LocalMesh m;
  const std::uint32_t side = std::uint32_t(m.positions.size());
  for (int k = 0; k <= slices; ++k) {
    glm::dvec2 c = ring(k, slices);
    glm::dvec3 nrm(c.x, 0, c.y);
    vert(m, {c.x, -1, c.y}, nrm);
    vert(m, {c.x, 1, c.y}, nrm);
  }
  for (int k = 0; k < slices; ++k) {
    std::uint32_t b0 = side + 2 * std::uint32_t(k), t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
    tri(m, b0, b1, t1);
    tri(m, b0, t1, t0);
  }
  for (int cap = 0; cap < 2; ++cap) {
    const double y = cap ? 1.0 : -1.0;
    const glm::dvec3 nrm(0, y, 0);
    std::uint32_t centre = vert(m, {0, y, 0}, nrm);
    std::uint32_t first = std::uint32_t(m.positions.size());
    for (int k = 0; k < slices; ++k) {
      glm::dvec2 c = ring(k, slices);
      vert(m, {c.x, y, c.y}, nrm);
    }
    for (int k = 0; k < slices; ++k) {
      std::uint32_t a = first + std::uint32_t(k), b = first + std::uint32_t((k + 1) % slices);
      if (cap)
        tri(m, centre, a, b);
      else
        tri(m, centre, b, a);
    }
  }
  return m;
}

LocalMesh make_cone(int slices) {
  LocalMesh m;
  // Side normal of a cone of height 2 and radius 1: (2 cos, 1, 2 sin) / sqrt(5).
  auto side_normal = [](glm::dvec2 c) { return glm::normalize(glm::dvec3(2 * c.x, 1, 2 * c.y)); };
  std::uint32_t base = std::uint32_t(m.positions.size());
  for (int k = 0; k <= slices; ++k) {
    glm::dvec2 c = ring(k, slices);
    vert(m, {c.x, -1, c.y}, side_normal(c));
  }
  for (int k = 0; k < slices; ++k) {
    // One apex vertex per slice, with the normal of the slice's middle (the apex has no normal).
    const double a = 2.0 * std::numbers::pi * (double(k) + 0.5) / double(slices);
    std::uint32_t apex = vert(m, {0, 1, 0}, side_normal({std::cos(a), -std::sin(a)}));
    tri(m, base + std::uint32_t(k), base + std::uint32_t(k) + 1, apex);
  }
  const glm::dvec3 down(0, -1, 0);
  std::uint32_t centre = vert(m, {0, -1, 0}, down);
  std::uint32_t first = std::uint32_t(m.positions.size());
  for (int k = 0; k < slices; ++k) {
    glm::dvec2 c = ring(k, slices);
    vert(m, {c.x, -1, c.y}, down);
  }
  for (int k = 0; k < slices; ++k)
    tri(m, centre, first + std::uint32_t((k + 1) % slices), first + std::uint32_t(k));
  return m;
}

} // namespace zc
