// Scene loaders: counts of the shipped scenes, the JSON and Blazek formats, seeded placement,
// bit-identical re-tessellation from ObjectDesc, textures only where used, and every bad input.
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/bezier.hpp"
#include "scene/load.hpp"
#include "scene/primitives.hpp"
#include "scene/tessellate.hpp"
#include "util/error.hpp"
#include "util/image_size.hpp"

namespace {

std::string src(const std::string& rel) {
  return std::string(ZCUBE_SOURCE_DIR) + "/" + rel;
}

bool same_bits(const zc::Vertex& a, const zc::Vertex& b) {
  return std::memcmp(&a, &b, sizeof(zc::Vertex)) == 0;
}

void expect_retessellates(const zc::Scene& s) {
  for (const auto& d : s.objects) {
    if (d.kind == "mesh") continue;
    zc::Tessellation t = zc::tessellate(d);
    ASSERT_EQ(t.vertices.size(), d.vertex_count) << d.text;
    ASSERT_EQ(t.triangles.size(), d.triangle_count) << d.text;
    for (std::size_t i = 0; i < t.vertices.size(); ++i)
      ASSERT_TRUE(same_bits(t.vertices[i], s.vertices[d.first_vertex + i])) << d.text << " v" << i;
    for (std::size_t i = 0; i < t.triangles.size(); ++i) {
      const auto& a = t.triangles[i];
      const auto& b = s.triangles[d.first_triangle + i];
      ASSERT_TRUE(a.v[0] == b.v[0] && a.v[1] == b.v[1] && a.v[2] == b.v[2] &&
                  a.material == b.material)
          << d.text << " t" << i;
    }
  }
}

} // namespace

TEST(SceneLoaders, DefaultTeapotCounts) {
  zc::Scene s = zc::load_scene(src("scenes/teapot.json"));
  EXPECT_EQ(s.triangles.size(), 3751u);
  EXPECT_EQ(s.vertices.size(), 1976u);
  EXPECT_EQ(s.width, 512);
  EXPECT_EQ(s.height, 512);
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_TRUE(s.uvs.empty());
  EXPECT_TRUE(s.textures.empty());
  EXPECT_FALSE(s.textured());
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].kind, "mesh");
  EXPECT_THROW(zc::tessellate(s.objects[0]), zc::InputError); // meshes ship triangles
  for (const auto& v : s.vertices)
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
}

TEST(SceneLoaders, BareObjAndSizeOverride) {
  zc::LoadOptions o;
  o.width = 320;
  o.height = 200;
  zc::Scene s = zc::load_scene(src("scenes/teapot/teapot_misc3d_3751.obj"), o);
  EXPECT_EQ(s.triangles.size(), 3751u);
  EXPECT_EQ(s.width, 320);
  EXPECT_EQ(s.height, 200);
  EXPECT_FALSE(s.lights.empty());
  EXPECT_GT(s.camera.eye.z, s.camera.target.z); // framing camera looks down -z
}

TEST(SceneLoaders, BoneIsoSurfaceCounts) {
  zc::Scene s = zc::load_scene(src("scenes/bone.json"));
  EXPECT_EQ(s.triangles.size(), 78738u);
  EXPECT_EQ(s.vertices.size(), 39485u);
}

TEST(SceneLoaders, SpotIsTextured) {
  zc::Scene s = zc::load_scene(src("scenes/spot.json"));
  EXPECT_EQ(s.triangles.size(), 5856u);
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.textures[0].width, 1024);
  EXPECT_EQ(s.textures[0].height, 1024);
  EXPECT_EQ(s.textures[0].rgb.size(), 1024u * 1024u * 3u);
  EXPECT_EQ(s.uvs.size(), s.vertices.size());
  EXPECT_TRUE(s.textured());
  bool uses = false;
  for (const auto& t : s.triangles)
    uses |= s.materials[t.material].texture == 0;
  EXPECT_TRUE(uses);
}

TEST(SceneLoaders, PolygonsFanNormalsAndDegenerates) {
  zc::Scene s = zc::load_scene(src("tests/data/scene/polygons.obj"));
  EXPECT_EQ(s.triangles.size(), 3u + 2u + 1u); // pentagon fan, quad fan, degenerate kept
  // The quad's corners carry the file normal (0,0,2) normalised.
  bool found = false;
  for (const auto& v : s.vertices)
    if (v.position.z == 1.0f) {
      EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
      found = true;
    }
  EXPECT_TRUE(found);
  // The pentagon's computed (area-weighted) normals face +z (counter-clockwise in the file).
  EXPECT_GT(s.vertices[s.triangles[0].v[1]].normal.z, 0.99f);
  const auto& d = s.triangles[5];
  EXPECT_EQ(d.v[0], d.v[1]); // f 1 1 2: zero area, legal, kept
}

TEST(SceneLoaders, JsonSceneFields) {
  zc::Scene s = zc::load_scene(src("scenes/primitives.json"));
  EXPECT_EQ(s.cull, zc::CullMode::Back);
  EXPECT_EQ(s.camera.fovy_deg, 40.0);
  EXPECT_EQ(s.camera.eye, glm::dvec3(0, 5, 16));
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_NEAR(s.ambient.r, 0.2f, 1e-6f);
  ASSERT_EQ(s.objects.size(), 4u + 16u);
  EXPECT_EQ(s.objects[0].kind, "cube");
  EXPECT_EQ(s.objects[0].triangle_count, 12u);
  EXPECT_EQ(s.objects[1].kind, "cone");
  EXPECT_EQ(s.objects[1].triangle_count, 64u);
  EXPECT_EQ(s.objects[2].kind, "cylinder");
  EXPECT_EQ(s.objects[2].triangle_count, 128u);
  EXPECT_EQ(s.objects[3].kind, "spheroid");
  EXPECT_EQ(s.objects[3].triangle_count, 8u * 256u);
  for (int i = 4; i < 20; ++i)
    EXPECT_EQ(s.objects[std::size_t(i)].triangle_count, 512u);
  for (const auto& d : s.objects)
    EXPECT_LE(d.text.size(), 160u) << d.text;
  EXPECT_TRUE(s.uvs.empty());
  EXPECT_TRUE(s.textures.empty());
  expect_retessellates(s);
}

TEST(SceneLoaders, ReplicatedPlacementIsDeterministic) {
  zc::Scene a = zc::load_scene(src("scenes/primitives.json"));
  zc::Scene b = zc::load_scene(src("scenes/primitives.json"));
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_EQ(
      std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(zc::Vertex)), 0);
  for (std::size_t i = 0; i < a.objects.size(); ++i)
    EXPECT_EQ(a.objects[i].text, b.objects[i].text);
  // Copies are inside the placement box (centres: [-5,5] x [-3.5,-1.8] x [-3,1]).
  for (std::size_t i = 4; i < a.objects.size(); ++i) {
    zc::ObjectSpec sp = zc::parse_object_text(a.objects[i].text);
    EXPECT_GE(sp.xf.translate.x, -5.0);
    EXPECT_LE(sp.xf.translate.x, 5.0);
    EXPECT_GE(sp.xf.translate.y, -3.5);
    EXPECT_LE(sp.xf.translate.y, -1.8);
  }
  // Two copies at distinct places.
  EXPECT_NE(a.objects[4].text, a.objects[5].text);
}

TEST(SceneLoaders, BlazekFigure9) {
  zc::Scene s = zc::load_scene(src("scenes/blazek_fig9.sdl"));
  ASSERT_EQ(s.objects.size(), 4u); // "num 3" cubes and one sphere
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(s.objects[std::size_t(i)].kind, "cube");
    EXPECT_EQ(s.materials[s.triangles[s.objects[std::size_t(i)].first_triangle].material].kd,
              glm::vec3(1, 0, 0));
  }
  EXPECT_EQ(s.objects[3].kind, "sphere");
  EXPECT_EQ(s.objects[3].triangle_count, 8u * 1024u); // recursion 5: 8 * 4^5
  EXPECT_NEAR(s.ambient.r, 0.40f, 1e-6f);
  EXPECT_EQ(s.background, glm::vec3(0));
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_LT(s.lights[0].direction.y, 0.0f); // from -1,1,1: shining down
  expect_retessellates(s);
}

TEST(SceneLoaders, NewellPatches) {
  zc::Scene a = zc::load_scene(src("scenes/teapot/teapot"));
  zc::Scene b = zc::load_scene(src("scenes/teapot/teapot.bpt"));
  EXPECT_EQ(a.triangles.size(), 32u * 2u * 64u);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  // The two file forms hold the same patches.
  EXPECT_EQ(
      std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(zc::Vertex)), 0);
  for (const auto& v : a.vertices) {
    EXPECT_TRUE(std::isfinite(v.normal.x) && std::isfinite(v.normal.y) &&
                std::isfinite(v.normal.z));
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
  }
  zc::Scene j = zc::load_scene(src("scenes/newell_teapot.json"));
  EXPECT_EQ(j.triangles.size(), 4096u);
  expect_retessellates(j);
}

TEST(SceneLoaders, PrimitivesAreOutwardAndConsistent) {
  const zc::LocalMesh meshes[] = {zc::make_sphere(2), zc::make_spheroid(2, {1, 0.5, 2}),
                                  zc::make_cube(), zc::make_cylinder(12), zc::make_cone(12)};
  for (const auto& m : meshes) {
    for (const auto& t : m.triangles) {
      glm::dvec3 p0 = m.positions[t.v[0]], p1 = m.positions[t.v[1]], p2 = m.positions[t.v[2]];
      glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
      ASSERT_GT(glm::length(n), 0.0);
      ASSERT_GT(glm::dot(n, (p0 + p1 + p2) / 3.0), 0.0); // convex about the origin: outward
      for (int k = 0; k < 3; ++k)
        ASSERT_GT(glm::dot(n, m.normals[t.v[k]]), 0.0);
    }
  }
  EXPECT_EQ(zc::make_sphere(3).triangles.size(), 512u);
  EXPECT_EQ(zc::make_sphere(3).positions.size(), 258u);
}

TEST(SceneLoaders, ObjectTextRoundTrips) {
  zc::ObjectSpec s;
  s.kind = "cylinder";
  s.slices = 17;
  s.xf.translate = {0.1, -2.5, 1e-3};
  s.xf.rotate_deg = {0, 108.86198107485642, 0};
  s.xf.scale = {0.4, 0.4, 0.4};
  s.material = 3;
  zc::ObjectSpec p = zc::parse_object_text(zc::object_text(s));
  EXPECT_EQ(p.kind, s.kind);
  EXPECT_EQ(p.slices, 17);
  EXPECT_EQ(p.xf.translate, s.xf.translate);
  EXPECT_EQ(p.xf.rotate_deg, s.xf.rotate_deg);
  EXPECT_EQ(p.xf.scale, s.xf.scale);
  EXPECT_EQ(p.material, 3u);
  EXPECT_THROW(zc::parse_object_text("torus mat 0"), zc::InputError);
  EXPECT_THROW(zc::parse_object_text("sphere recursion 5"), zc::InputError); // no mat
}

// --- bad input: one InputError naming the file, the line and the reason -----------------------

struct BadCase {
  const char* file;
  int line;
  const char* reason; // a fragment of the reason
};

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, ThrowsInputErrorWithFileLineReason) {
  const BadCase& c = GetParam();
  const std::string path = src(std::string("tests/data/bad/") + c.file);
  try {
    zc::load_scene(path);
    FAIL() << c.file << " loaded without error";
  } catch (const zc::InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.line(), c.line) << what;
    EXPECT_NE(what.find(c.reason), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    // The message names the file at fault (the scene, or the MTL/OBJ it references).
    const std::string base = std::string(c.file).substr(0, std::string(c.file).find('.'));
    EXPECT_NE(e.file().find(base), std::string::npos) << what;
    if (c.line > 0) {
      EXPECT_NE(what.find(":" + std::to_string(c.line) + ":"), std::string::npos) << what;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    SceneLoaders, BadInput,
    ::testing::Values(BadCase{"face_index_range.obj", 4, "vertex index 4 out of range"},
                      BadCase{"nan_coord.obj", 2, "not a finite number"},
                      BadCase{"inf_coord.obj", 3, "out of the range of a float"},
                      BadCase{"truncated_vertex.obj", 5, "'v' needs 3 numbers"},
                      BadCase{"short_face.obj", 4, "at least 3 vertices"},
                      BadCase{"garbage_face.obj", 4, "bad face vertex"},
                      BadCase{"missing_mtl.obj", 1, "material library not found"},
                      BadCase{"bad_kd.obj", 3, "'Kd' needs 3 numbers"}, // reported in bad_kd.mtl
                      BadCase{"missing_texture.obj", 3, "texture file not found"},
                      BadCase{"syntax.json", 5, "JSON"}, BadCase{"truncated.json", 5, "JSON"},
                      BadCase{"size_zero.json", 0, "image.width: expected an integer in 1..16384"},
                      BadCase{"size_huge.json", 0, "image.width: expected an integer in 1..16384"},
                      BadCase{"missing_mesh.json", 0, "mesh file not found"},
                      BadCase{"unknown_type.json", 0, "unknown object type 'teapot'"},
                      BadCase{"unknown_keyword.sdl", 3, "unknown keyword 'frobnicate'"},
                      BadCase{"bad_recursion.sdl", 2, "recursion must be an integer in 0..9"},
                      BadCase{"bad_color.sdl", 2, "unknown colour 'octarine'"},
                      BadCase{"truncated.sdl", 2, "'scale' needs a value"},
                      BadCase{"too_many_triangles.json", 0, "over its budget of 67108864"},
                      BadCase{"too_many_triangles.sdl", 3, "40 x this sphere would take"},
                      BadCase{"bezier_index.teaset", 2, "control-point index 99 out of range"},
                      BadCase{"bezier_truncated.teaset", 3, "truncated file"}),
    [](const ::testing::TestParamInfo<BadCase>& i) {
      std::string n = i.param.file;
      for (char& ch : n)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return n;
    });

TEST(SceneLoaders, MissingSceneFile) {
  try {
    zc::load_scene(src("tests/data/bad/no_such_scene.json"));
    FAIL();
  } catch (const zc::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_scene.json: file not found"), std::string::npos);
  }
}

TEST(SceneLoaders, OverrideCannotBeAbsurd) {
  zc::LoadOptions o;
  o.width = zc::kMaxImageSide + 1;
  EXPECT_THROW(zc::load_scene(src("scenes/blazek_fig9.sdl"), o), zc::InputError);
}

TEST(SceneLoaders, ObjFacesGetTheMaterialTheirUsemtlNames) {
  zc::Scene s = zc::load_scene(src("tests/data/scene/materials.obj"));
  ASSERT_EQ(s.triangles.size(), 4u);
  ASSERT_EQ(s.materials.size(), 4u); // the default, then red, green, red as the library lists them
  EXPECT_EQ(s.materials[1].kd, glm::vec3(1, 0, 0));
  EXPECT_EQ(s.materials[2].kd, glm::vec3(0, 1, 0));
  EXPECT_EQ(s.triangles[0].material, 0u); // before any usemtl
  EXPECT_EQ(s.triangles[1].material, 2u); // green, across the group
  EXPECT_EQ(s.triangles[2].material, 0u); // an unknown name falls back to the default
  EXPECT_EQ(s.triangles[3].material, 1u); // the first red
  EXPECT_EQ(s.vertices[s.triangles[3].v[0]].position, glm::vec3(0, 0, 0)); // -4 of 4 vertices
}

// The triangle budget is checked before tessellating: a closed form per primitive, the patch count
// of a Bezier file, and an OBJ's faces before they join the scene.
TEST(SceneLoaders, TriangleCountIsTheTessellationsWithoutTessellating) {
  std::vector<zc::ObjectSpec> specs(6);
  specs[0].recursion = 4;
  specs[1].kind = "spheroid";
  specs[1].recursion = 2;
  specs[2].kind = "cube";
  specs[3].kind = "cone";
  specs[3].slices = 7;
  specs[4].kind = "cylinder";
  specs[4].slices = 9;
  specs[5].kind = "bezier";
  specs[5].file = src("scenes/teapot/teapot.bpt");
  specs[5].level = 5;
  for (const auto& s : specs)
    EXPECT_EQ(zc::triangle_count(s), zc::tessellate(s, 0).triangles.size()) << s.kind;
}

TEST(SceneLoaders, TriangleBudgetRefusesTheObjectThatWouldExceedIt) {
  zc::LoadOptions o;
  o.max_triangles = 12 + 2 * 512; // the cube and two recursion-3 spheres, not a third
  const std::string dir = ::testing::TempDir();
  const std::string path = dir + "/budget.json";
  std::ofstream(path) << R"({"objects": ["cube", {"type": "sphere", "recursion": 3},
    {"type": "sphere", "recursion": 3}, {"type": "sphere", "recursion": 3}]})";
  try {
    zc::load_scene(path, o);
    FAIL() << "a scene over its triangle budget loaded";
  } catch (const zc::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("objects[3]: this sphere would take the scene to 1036 + "
                                         "1 x 512 triangles, over its budget of 1036"),
              std::string::npos)
        << e.what();
  }
  o.max_triangles = 12 + 3 * 512;
  EXPECT_EQ(zc::load_scene(path, o).triangles.size(), 12u + 3 * 512);
  o.max_triangles = 1000;
  try {
    zc::load_scene(src("scenes/bunny/stanford-bunny.obj"), o);
    FAIL() << "a mesh over the triangle budget loaded";
  } catch (const zc::InputError& e) {
    EXPECT_NE(e.file().find("stanford-bunny.obj"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("over its budget of 1000"), std::string::npos) << e.what();
  }
}
