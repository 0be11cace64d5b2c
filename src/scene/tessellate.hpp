#pragma once
// Object descriptions and their tessellation. Blazek's node-initiated and object-forwarding methods
// ship an object's one-line description (~100 bytes) instead of its polygons and let the node
// tessellate it (thesis ch. V). The loaders build every primitive *through* its text, so
// tessellate(desc) reproduces the scene's vertex and triangle ranges bit for bit.
//
// Text grammar (one line, tokens separated by spaces, defaults omitted):
//   <kind> [recursion R] [slices N] [level L] [radii x,y,z] [translate x,y,z] [rotate x,y,z]
//          [scale x,y,z] [matrix m00,m01,...,m33] mat M [color r,g,b] [file PATH-to-end-of-line]
// kind: sphere spheroid cube cone cylinder bezier mesh. rotate is in degrees about x, then y, then
// z; the object matrix is translate * (matrix, or Rz*Ry*Rx*scale); matrix is column-major. Numbers
// are printed in their shortest round-trip form, so parsing gives back the same doubles.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace zc {

struct ObjectTransform {
  glm::dvec3 translate{0}, rotate_deg{0}, scale{1};
  bool has_matrix = false;
  glm::dmat4 matrix{1.0};
  glm::dmat4 to_matrix() const;
};

struct ObjectSpec {
  std::string kind = "sphere";
  int recursion = 3;               // sphere, spheroid: octahedron subdivisions
  int slices = 32;                 // cone, cylinder
  int level = 8;                   // bezier: grid steps per patch side
  glm::dvec3 radii{1.0, 0.5, 1.0}; // spheroid
  std::string file;                // bezier, mesh
  ObjectTransform xf;
  std::uint32_t material = 0; // index into Scene::materials
  glm::vec3 color{0.8f};      // the material's colour, carried for the reader (not used)
};

std::string object_text(const ObjectSpec& s);
// Throws InputError("<object>", 0, reason) on a malformed description.
ObjectSpec parse_object_text(const std::string& text);

struct Tessellation {
  std::vector<Vertex> vertices;
  std::vector<Triangle> triangles; // indices already offset by the object's first vertex
};

// Tessellates a primitive or Bezier object whose vertices start at first_vertex.
// Mesh objects cannot be re-tessellated (their triangles come from a file, not a description):
// throws InputError naming the mesh file.
Tessellation tessellate(const ObjectSpec& s, std::uint32_t first_vertex);

// Re-tessellates a scene object from its description: equal, bit for bit, to the scene's
// vertices [first_vertex, +vertex_count) and triangles [first_triangle, +triangle_count).
Tessellation tessellate(const ObjectDesc& d);

// How many triangles tessellate(s) yields, without tessellating (a Bezier object reads its file).
std::uint64_t triangle_count(const ObjectSpec& s);

// Throws InputError("<object>", 0, reason) when `copies` more objects of `each` triangles would
// take the scene over its triangle budget.
void check_triangle_budget(const Scene& scene, std::uint64_t copies, std::uint64_t each,
                           const std::string& what);

// Appends a primitive or Bezier object to the scene (through its text) and records its ObjectDesc;
// checks the scene's triangle budget first.
void add_object(Scene& scene, const ObjectSpec& s);

// Index of a plain material of colour kd (reused when one already exists).
std::uint32_t color_material(Scene& scene, const glm::vec3& kd);

} // namespace zc
