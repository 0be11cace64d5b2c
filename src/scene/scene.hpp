#pragma once
// The scene as every part of zcube sees it: a camera, an image size, lights, and an indexed
// triangle soup in world space (Charles et al. §4: "a set of vertices and a set of triangles").
// Triangle ids are the indices into `triangles`; they are global and stable, and they break depth
// ties (equal depth: the lower id wins), so any partition of the work reproduces the same image.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/camera.hpp"

namespace zc {

struct DirectionalLight {
  glm::vec3 direction{-1, -1, -1}; // direction the light travels (towards the scene)
  glm::vec3 color{1, 1, 1};
};

// A texture in memory, RGB8, rows top to bottom. Loaded only when a material uses it.
struct Texture {
  std::string path;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
};

enum class TextureFilter { Nearest, Bilinear };

struct Material {
  std::string name;
  glm::vec3 kd{0.8f, 0.8f, 0.8f}; // diffuse colour, 0..1
  int texture = -1;               // index into Scene::textures, -1 = none
};

struct Vertex {
  glm::vec3 position{0};
  glm::vec3 normal{0, 0, 1};
};

struct Triangle {
  std::uint32_t v[3] = {0, 0, 0}; // indices into Scene::vertices (and Scene::uvs when textured)
  std::uint32_t material = 0;     // index into Scene::materials
};

// A triangle as a node holds it: its global id (its index in Scene::triangles, the depth tie-break
// that keeps every algorithm's picture the sequential renderer's) and its record, whose vertex
// numbers index the scene's vertices or the node's own (a tessellated object's).
struct TriangleRecord {
  std::uint32_t id = 0;
  Triangle tri;
};

// A primitive as a scene description states it (Blazek ch. IV): kept so that methods which ship
// descriptions instead of polygons (node initiated, object forwarding) can re-tessellate it on a
// node. Tessellating `desc` yields exactly triangles [first_triangle,
// first_triangle+triangle_count) and vertices [first_vertex, first_vertex+vertex_count) of the
// scene, bit for bit.
struct ObjectDesc {
  std::string kind; // "sphere", "cube", "cone", "cylinder", "spheroid", "bezier", "mesh"
  std::string text; // canonical one-line description (what the host would send), ~100 bytes
  std::uint32_t first_vertex = 0, vertex_count = 0;
  std::uint32_t first_triangle = 0, triangle_count = 0;
};

enum class CullMode { None, Back };

// The most triangles a scene may hold unless the loader is told otherwise (LoadOptions): 2^26 =
// 67,108,864, four times Blazek's largest workload (2048 spheres of 8192 triangles), about 2 GB of
// vertices and triangles. Checked before an object is tessellated, so a scene that asks for more
// fails at once, naming the object, instead of filling the host's memory.
constexpr std::uint64_t kMaxSceneTriangles = std::uint64_t(1) << 26;

struct Scene {
  std::string path; // where it was loaded from (for messages and reports)
  Camera camera;
  int width = 512;
  int height = 512;
  glm::vec3 background{0, 0, 0};
  glm::vec3 ambient{0.15f, 0.15f, 0.15f};
  std::vector<DirectionalLight> lights;
  CullMode cull = CullMode::None;
  TextureFilter filter = TextureFilter::Bilinear;

  std::vector<Vertex> vertices;
  std::vector<glm::vec2> uvs; // empty for an untextured scene; else one per vertex
  std::vector<Triangle> triangles;
  std::vector<Material> materials{Material{}};
  std::vector<Texture> textures;
  std::vector<ObjectDesc> objects;
  std::uint64_t triangle_budget = kMaxSceneTriangles; // set by the loader (LoadOptions)

  bool textured() const { return !textures.empty() && !uvs.empty(); }
  // The texture coordinates set-up reads (NodeRenderer::setup), nullptr when untextured.
  const glm::vec2* uvs_if_textured() const { return textured() ? uvs.data() : nullptr; }
};

// The bounding box of the scene's vertices.
Bounds scene_bounds(const Scene& s);

// What a node program derives from the whole scene (its bounds for the clip planes, whether its
// triangles use more than one material). The simulator's nodes share one scene, so it works this
// out once for all of them (NodeContext::scene_facts) instead of once a node.
struct SceneFacts {
  Bounds bounds;
  bool several_materials = false;
};
SceneFacts scene_facts(const Scene& s);

} // namespace zc
