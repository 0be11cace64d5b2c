#include "scene/tessellate.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "scene/bezier.hpp"
#include "scene/primitives.hpp"
#include "scene/text.hpp"
#include "util/error.hpp"

namespace zc {

glm::dmat4 ObjectTransform::to_matrix() const {
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), translate);
  if (has_matrix) return m * matrix;
  m = glm::rotate(m, glm::radians(rotate_deg.z), glm::dvec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rotate_deg.y), glm::dvec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotate_deg.x), glm::dvec3(1, 0, 0));
  return glm::scale(m, scale);
}

namespace {

std::string vec(const glm::dvec3& v) {
  return text::fmt(v.x) + "," + text::fmt(v.y) + "," + text::fmt(v.z);
}

[[noreturn]] void bad(const std::string& why) {
  throw InputError("<object>", 0, why);
}

glm::dvec3 parse_vec(std::string_view s, const char* key) {
  auto tok = text::split(s, true);
  if (tok.size() != 3) bad(std::string(key) + " needs x,y,z");
  glm::dvec3 v;
  for (int k = 0; k < 3; ++k) {
    auto d = text::to_double(tok[std::size_t(k)]);
    if (!d) bad(std::string(key) + ": not a finite number");
    v[k] = *d;
  }
  return v;
}

int parse_int(std::string_view s, const char* key, int lo, int hi) {
  auto v = text::to_int(s);
  if (!v || *v < lo || *v > hi)
    bad(std::string(key) + " must be an integer in " + std::to_string(lo) + ".." +
        std::to_string(hi));
  return int(*v);
}

} // namespace

std::string object_text(const ObjectSpec& s) {
  std::string t = s.kind;
  if (s.kind == "sphere" || s.kind == "spheroid") t += " recursion " + std::to_string(s.recursion);
  if (s.kind == "spheroid") t += " radii " + vec(s.radii);
  if (s.kind == "cone" || s.kind == "cylinder") t += " slices " + std::to_string(s.slices);
  if (s.kind == "bezier") t += " level " + std::to_string(s.level);
  if (s.xf.translate != glm::dvec3(0)) t += " translate " + vec(s.xf.translate);
  if (s.xf.has_matrix) {
    t += " matrix ";
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        t += text::fmt(s.xf.matrix[c][r]) + (c == 3 && r == 3 ? "" : ",");
  } else {
    if (s.xf.rotate_deg != glm::dvec3(0)) t += " rotate " + vec(s.xf.rotate_deg);
    if (s.xf.scale != glm::dvec3(1)) t += " scale " + vec(s.xf.scale);
  }
  t += " mat " + std::to_string(s.material);
  t += " color " + text::fmt(s.color.r) + "," + text::fmt(s.color.g) + "," + text::fmt(s.color.b);
  if (!s.file.empty()) t += " file " + s.file;
  return t;
}

ObjectSpec parse_object_text(const std::string& line) {
  ObjectSpec s;
  std::string_view rest = text::trim(line);
  auto next = [&]() {
    std::size_t i = 0;
    while (i < rest.size() && rest[i] == ' ')
      ++i;
    std::size_t j = rest.find(' ', i);
    if (j == std::string_view::npos) j = rest.size();
    std::string_view tok = rest.substr(i, j - i);
    rest = rest.substr(j);
    return tok;
  };
  s.kind = std::string(next());
  if (s.kind != "sphere" && s.kind != "spheroid" && s.kind != "cube" && s.kind != "cone" &&
      s.kind != "cylinder" && s.kind != "bezier" && s.kind != "mesh")
    bad("unknown object kind '" + s.kind + "'");
  bool have_mat = false;
  for (;;) {
    std::string_view key = next();
    if (key.empty()) break;
    if (key == "file") {
      s.file = std::string(text::trim(rest));
      if (s.file.empty()) bad("file needs a path");
      break;
    }
    std::string_view val = next();
    if (val.empty()) bad(std::string(key) + " needs a value");
    if (key == "recursion")
      s.recursion = parse_int(val, "recursion", 0, kMaxRecursion);
    else if (key == "slices")
      s.slices = parse_int(val, "slices", 3, kMaxSlices);
    else if (key == "level")
      s.level = parse_int(val, "level", 1, kMaxBezierLevel);
    else if (key == "radii")
      s.radii = parse_vec(val, "radii");
    else if (key == "translate")
      s.xf.translate = parse_vec(val, "translate");
    else if (key == "rotate")
      s.xf.rotate_deg = parse_vec(val, "rotate");
    else if (key == "scale")
      s.xf.scale = parse_vec(val, "scale");
    else if (key == "mat") {
      s.material = std::uint32_t(parse_int(val, "mat", 0, 1 << 30));
      have_mat = true;
    } else if (key == "color") {
      glm::dvec3 c = parse_vec(val, "color");
      s.color = glm::vec3(c);
    } else if (key == "matrix") {
      auto tok = text::split(val, true);
      if (tok.size() != 16) bad("matrix needs 16 numbers");
      for (int k = 0; k < 16; ++k) {
        auto d = text::to_double(tok[std::size_t(k)]);
        if (!d) bad("matrix: not a finite number");
        s.xf.matrix[k / 4][k % 4] = *d;
      }
      s.xf.has_matrix = true;
    } else
      bad("unknown key '" + std::string(key) + "'");
  }
  if (!have_mat) bad("missing 'mat'");
  if ((s.kind == "bezier" || s.kind == "mesh") && s.file.empty()) bad(s.kind + " needs a file");
  return s;
}

Tessellation tessellate(const ObjectSpec& s, std::uint32_t first_vertex) {
  LocalMesh m;
  const LocalMesh* mesh = &m; // a sphere: the process's kept one, read without a copy
  if (s.kind == "sphere")
    mesh = &sphere_mesh(s.recursion, m);
  else if (s.kind == "spheroid")
    m = make_spheroid(s.recursion, s.radii);
  else if (s.kind == "cube")
    m = make_cube();
  else if (s.kind == "cone")
    m = make_cone(s.slices);
  else if (s.kind == "cylinder")
    m = make_cylinder(s.slices);
  else if (s.kind == "bezier")
    m = tessellate_patches(*read_bezier_file(s.file), s.level);
  else if (s.kind == "mesh")
    throw InputError(s.file, 0,
                     "mesh objects cannot be re-tessellated from their description: a mesh's "
                     "triangles come from its file, so ship the triangles instead");
  else
    bad("unknown object kind '" + s.kind + "'");

  const glm::dmat4 M = s.xf.to_matrix();
  const glm::dmat3 N = glm::transpose(glm::inverse(glm::dmat3(M)));
  const bool flip = glm::determinant(glm::dmat3(M)) < 0; // a mirror turns the winding over
  Tessellation t;
  t.vertices.resize(mesh->positions.size());
  for (std::size_t i = 0; i < mesh->positions.size(); ++i) {
    t.vertices[i].position = glm::vec3(glm::dvec3(M * glm::dvec4(mesh->positions[i], 1.0)));
    glm::dvec3 n = N * mesh->normals[i];
    double len = glm::length(n);
    t.vertices[i].normal = glm::vec3(len > 0 ? n / len : glm::dvec3(0, 0, 1));
  }
  if (mesh == &m)
    t.triangles = std::move(m.triangles);
  else
    t.triangles = mesh->triangles;
  for (auto& tr : t.triangles) {
    for (auto& v : tr.v)
      v += first_vertex;
    if (flip) std::swap(tr.v[1], tr.v[2]);
    tr.material = s.material;
  }
  return t;
}

Tessellation tessellate(const ObjectDesc& d) {
  return tessellate(parse_object_text(d.text), d.first_vertex);
}

std::uint64_t triangle_count(const ObjectSpec& s) {
  if (s.kind == "sphere" || s.kind == "spheroid") return std::uint64_t(8) << (2 * s.recursion);
  if (s.kind == "cube") return 12;
  if (s.kind == "cone") return 2 * std::uint64_t(s.slices);
  if (s.kind == "cylinder") return 4 * std::uint64_t(s.slices);
  if (s.kind == "bezier")
    return read_bezier_file(s.file)->size() * 2 * std::uint64_t(s.level) * std::uint64_t(s.level);
  bad("no triangle count for object kind '" + s.kind + "'");
}

void check_triangle_budget(const Scene& scene, std::uint64_t copies, std::uint64_t each,
                           const std::string& what) {
  const std::uint64_t have = scene.triangles.size(), room = scene.triangle_budget;
  if (have <= room && (each == 0 || copies <= (room - have) / each)) return;
  bad(what + " would take the scene to " + std::to_string(have) + " + " + std::to_string(copies) +
      " x " + std::to_string(each) + " triangles, over its budget of " + std::to_string(room) +
      (room == kMaxSceneTriangles ? " (zcube's limit)" : ""));
}

void add_object(Scene& scene, const ObjectSpec& spec) {
  ObjectDesc d;
  d.kind = spec.kind;
  d.text = object_text(spec);
  const ObjectSpec parsed = parse_object_text(d.text);
  check_triangle_budget(scene, 1, triangle_count(parsed), "this " + spec.kind);
  d.first_vertex = std::uint32_t(scene.vertices.size());
  d.first_triangle = std::uint32_t(scene.triangles.size());
  // Built from the text itself, so the description is exactly what was tessellated.
  Tessellation t = tessellate(parsed, d.first_vertex);
  d.vertex_count = std::uint32_t(t.vertices.size());
  d.triangle_count = std::uint32_t(t.triangles.size());
  scene.vertices.insert(scene.vertices.end(), t.vertices.begin(), t.vertices.end());
  scene.triangles.insert(scene.triangles.end(), t.triangles.begin(), t.triangles.end());
  scene.objects.push_back(std::move(d));
}

std::uint32_t color_material(Scene& scene, const glm::vec3& kd) {
  for (std::size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].texture < 0 && scene.materials[i].kd == kd &&
        scene.materials[i].name.rfind("color", 0) == 0)
      return std::uint32_t(i);
  Material m;
  m.name = "color " + text::fmt(kd.r) + "," + text::fmt(kd.g) + "," + text::fmt(kd.b);
  m.kd = kd;
  scene.materials.push_back(m);
  return std::uint32_t(scene.materials.size() - 1);
}

} // namespace zc
