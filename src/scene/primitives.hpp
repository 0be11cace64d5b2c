#pragma once
// Blazek's primitives (thesis ch. IV "Primitives", Figure 8), tessellated in object space with
// analytic normals: sphere (recursive subdivision of an octahedron, ch. II "Tessellation"), cube,
// cone, cylinder and spheroid. Every primitive fits the cube [-1,1]^3 and is wound
// counter-clockwise seen from outside. Triangle indices are local (0-based) and material 0.
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace zc {

struct LocalMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals; // unit length, one per position
  std::vector<Triangle> triangles;
};

constexpr int kMaxRecursion = 9; // 8 * 4^9 = 2,097,152 triangles per sphere
constexpr int kMaxSlices = 4096;

// 8 * 4^recursion triangles, 4^(recursion+1) + 2 vertices.
LocalMesh make_sphere(int recursion);
// The same without a copy: the process's kept mesh of that level, or (a level not kept) `built`,
// into which it is built.
const LocalMesh& sphere_mesh(int recursion, LocalMesh& built);
// The sphere stretched to radii (rx, ry, rz); normals are the ellipsoid's gradient.
LocalMesh make_spheroid(int recursion, const glm::dvec3& radii);
// 12 triangles, 24 vertices (flat normal per face).
LocalMesh make_cube();
// Axis y, radius 1, y in [-1, 1], with both caps: 4 * slices triangles.
LocalMesh make_cylinder(int slices);
// Apex at y = 1, base of radius 1 at y = -1, with the base cap: 2 * slices triangles.
LocalMesh make_cone(int slices);

} // namespace zc
