// Wavefront OBJ + MTL (Malerich 2017: models come as .obj with a .mtl that holds the textures).
// The geometry comes from zcube's own checking pass (scene/obj_text: tinyobjloader is lenient, so
// every line had to be checked and parsed anyway, and parsing it a second time through
// tinyobjloader's istream reader ran at 50 MB/s); the materials come from tinyobjloader, which
// reads the material libraries and assigns the usemtl ids. Every fault is an InputError with its
// line number.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include <tiny_obj_loader.h>

#include "scene/loaders.hpp"
#include "scene/obj_text.hpp"
#include "scene/text.hpp"
#include "util/error.hpp"
#include "util/input_file.hpp"

namespace zc {

namespace {

struct Line {
  std::string_view text;
  int number;
};

template <class F> void for_lines(const std::string& s, F&& f) {
  std::size_t i = 0;
  int n = 0;
  while (i < s.size()) {
    std::size_t j = s.find('\n', i);
    if (j == std::string::npos) j = s.size();
    ++n;
    std::string_view l = text::trim(std::string_view(s).substr(i, j - i));
    if (auto h = l.find('#'); h != std::string_view::npos) l = text::trim(l.substr(0, h));
    if (!l.empty()) f(Line{l, n});
    i = j + 1;
  }
}

void need_numbers(const std::string& file, const Line& l, std::size_t min_count,
                  std::size_t max_count) {
  auto tok = text::split(l.text);
  if (tok.size() < min_count + 1)
    throw InputError(file, l.number,
                     "'" + std::string(tok[0]) + "' needs " + std::to_string(min_count) +
                         " numbers");
  for (std::size_t k = 1; k < tok.size() && k <= max_count; ++k)
    if (!text::to_float(tok[k])) throw InputError(file, l.number, text::float_problem(tok[k]));
}

struct TexRef {
  std::string path, mtl; // texture file, and the MTL naming it at `line`
  int line = 0;
};

struct MtlInfo {
  std::map<std::string, TexRef> texture; // by material name
};

MtlInfo check_mtl(const std::string& path, const std::string& obj_file, int obj_line) {
  if (const auto p = referenced_file_problem("material library", path); !p.empty())
    throw InputError(obj_file, obj_line, p);
  const std::string s = text::read_file(path);
  MtlInfo info;
  std::string current;
  const std::string dir = text::directory_of(path);
  for_lines(s, [&](const Line& l) {
    std::string_view k = text::keyword(l.text);
    auto tok = text::split(l.text);
    if (k == "newmtl") {
      if (tok.size() < 2) throw InputError(path, l.number, "newmtl needs a name");
      current = std::string(text::trim(l.text.substr(6)));
      return;
    }
    if (current.empty())
      throw InputError(path, l.number, "'" + std::string(k) + "' before any newmtl");
    if (k == "Kd" || k == "Ka" || k == "Ks" || k == "Ke" || k == "Tf") {
      if (tok.size() >= 2 && (tok[1] == "spectral" || tok[1] == "xyz")) return;
      need_numbers(path, l, 3, 3);
    } else if (k == "Ns" || k == "Ni" || k == "d" || k == "Tr" || k == "illum") {
      need_numbers(path, l, 1, 1);
    } else if (k == "map_Kd") {
      if (tok.size() < 2) throw InputError(path, l.number, "map_Kd needs a file name");
      std::string tex = text::join_path(dir, std::string(tok.back())); // options come first
      if (const auto p = referenced_file_problem("texture file", tex); !p.empty())
        throw InputError(path, l.number, p);
      info.texture[current] = TexRef{tex, path, l.number};
    }
  });
  return info;
}

// Face-varying corners (v, vn, vt) become zcube vertices, first come first numbered; vt takes
// part only when the mesh is textured (pay only for what is used).
struct Key {
  int v, n, t;
  bool operator==(const Key& o) const { return v == o.v && n == o.n && t == o.t; }
};

// The OBJ file checked and read, with the textures of every material library it names (by
// material name).
ObjText read_checked_obj(const std::string& path, std::map<std::string, TexRef>& textures) {
  if (const auto p = input_file_problem(path); !p.empty())
    throw InputError(path, 0, p == "not found" ? "mesh file not found" : p);
  std::string src = text::read_file(path);
  if (src.starts_with("\xEF\xBB\xBF")) src.erase(0, 3); // a UTF-8 byte-order mark
  const std::string dir = text::directory_of(path);
  return read_obj_text(path, src, [&](const std::string& file, int line) {
    for (auto& [name, tex] : check_mtl(text::join_path(dir, file), path, line).texture)
      textures[name] = tex;
  });
}

// tinyobjloader reads the material lines alone (obj_text.hpp): segment k's material id is the
// k-th marker face's. Returns the segments' material ids; the materials into `mats`.
std::vector<int> segment_materials(const std::string& path, const ObjText& obj,
                                   std::vector<tinyobj::material_t>& mats) {
  const std::string dir = text::directory_of(path);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::string warn, err;
  std::istringstream in(obj.materials_obj);
  tinyobj::MaterialFileReader materials(dir.empty() ? std::string() : dir + "/");
  if (!tinyobj::LoadObj(&attrib, &shapes, &mats, &warn, &err, &in, &materials,
                        /*triangulate=*/false))
    throw InputError(path, 0, "cannot parse OBJ: " + std::string(text::trim(err)));
  std::vector<int> segment_material;
  for (const auto& sh : shapes)
    segment_material.insert(segment_material.end(), sh.mesh.material_ids.begin(),
                            sh.mesh.material_ids.end());
  if (segment_material.size() <= std::size_t(obj.face_segment.back())) // segments never decrease
    throw std::logic_error("OBJ: tinyobjloader dropped a material marker of " + path);
  return segment_material;
}

// Materials appended to the scene; textures loaded only where a material uses one. Returns which
// materials are textured.
std::vector<bool> add_materials(Scene& scene, const std::vector<tinyobj::material_t>& mats,
                                const std::map<std::string, TexRef>& textures) {
  std::vector<bool> mat_textured(mats.size(), false);
  for (std::size_t i = 0; i < mats.size(); ++i) {
    Material m;
    m.name = mats[i].name;
    m.kd = glm::vec3(mats[i].diffuse[0], mats[i].diffuse[1], mats[i].diffuse[2]);
    auto it = textures.find(mats[i].name);
    if (it != textures.end()) {
      const TexRef& ref = it->second;
      int found = -1;
      for (std::size_t t = 0; t < scene.textures.size(); ++t)
        if (scene.textures[t].path == ref.path) found = int(t);
      if (found < 0) {
        scene.textures.push_back(load_texture(ref.path, ref.mtl, ref.line));
        found = int(scene.textures.size() - 1);
      }
      m.texture = found;
      m.kd = glm::vec3(1.0f); // the texture is the diffuse colour
      mat_textured[i] = true;
    }
    scene.materials.push_back(m);
  }
  return mat_textured;
}

// The mesh's corners as keys and its faces as triangles over them (their material ids in the
// scene: `mat_base` plus the file's, or `default_material`).
struct Faces {
  std::vector<Key> keys;
  std::vector<Triangle> tris;
};
Faces make_faces(const ObjText& obj, const std::vector<int>& face_materials, std::size_t nmats,
                 bool textured, std::uint32_t mat_base, std::uint32_t default_material,
                 bool flip_winding) {
  // Keys sharing a position are chained from it (most positions have one key): a lookup is a
  // short walk, with no hashing and no allocation per key.
  constexpr std::uint32_t kNone = ~0u;
  std::vector<std::uint32_t> first_key(obj.positions.size() / 3, kNone), next_key;
  Faces out;
  std::vector<Key>& keys = out.keys;
  keys.reserve(obj.positions.size() / 3);
  next_key.reserve(obj.positions.size() / 3);
  const auto key_id = [&](const Key& k) {
    std::uint32_t& head = first_key[std::size_t(k.v)];
    for (std::uint32_t i = head; i != kNone; i = next_key[i])
      if (keys[i] == k) return i;
    keys.push_back(k);
    next_key.push_back(head);
    head = std::uint32_t(keys.size() - 1);
    return head;
  };
  out.tris.reserve(obj.face_size.size());
  std::size_t off = 0;
  for (std::size_t f = 0; f < obj.face_size.size(); ++f) {
    const std::size_t nv = obj.face_size[f];
    std::uint32_t corner[256];
    for (std::size_t c = 0; c < nv; ++c) {
      const ObjCorner& ix = obj.corners[off + c];
      Key k{ix.v, ix.n, textured ? ix.t : -1};
      corner[c] = key_id(k);
    }
    const int mid = face_materials[f];
    std::uint32_t mat =
        mid >= 0 && std::size_t(mid) < nmats ? mat_base + std::uint32_t(mid) : default_material;
    for (std::size_t c = 1; c + 1 < nv; ++c) { // a polygon becomes a fan around its first corner
      Triangle t;
      t.v[0] = corner[0];
      t.v[1] = corner[flip_winding ? c + 1 : c];
      t.v[2] = corner[flip_winding ? c : c + 1];
      t.material = mat;
      out.tris.push_back(t);
    }
    off += nv;
  }
  return out;
}

glm::dvec3 position(const ObjText& obj, int v) {
  return glm::dvec3(obj.positions[3 * std::size_t(v)], obj.positions[3 * std::size_t(v) + 1],
                    obj.positions[3 * std::size_t(v) + 2]);
}

// The normal the file gives a corner, or zero.
glm::dvec3 file_normal(const ObjText& obj, const Key& k) {
  if (k.n < 0 || 3 * std::size_t(k.n) + 2 >= obj.normals.size()) return glm::dvec3(0);
  return glm::dvec3(obj.normals[3 * std::size_t(k.n)], obj.normals[3 * std::size_t(k.n) + 1],
                    obj.normals[3 * std::size_t(k.n) + 2]);
}

// Area-weighted position normals, for corners the file gives no normal (empty when none lacks
// one).
std::vector<glm::dvec3> area_normals(const ObjText& obj, const Faces& faces) {
  bool need_area = false; // some corner has no usable file normal
  for (const auto& k : faces.keys)
    need_area |= !(glm::length(file_normal(obj, k)) > 0);
  std::vector<glm::dvec3> area_n;
  if (!need_area) return area_n;
  area_n.assign(obj.positions.size() / 3, glm::dvec3(0));
  for (const auto& t : faces.tris) {
    const int a = faces.keys[t.v[0]].v, b = faces.keys[t.v[1]].v, c = faces.keys[t.v[2]].v;
    glm::dvec3 n = glm::cross(position(obj, b) - position(obj, a),
                              position(obj, c) - position(obj, a)); // |n| = 2 * area
    area_n[std::size_t(a)] += n;
    area_n[std::size_t(b)] += n;
    area_n[std::size_t(c)] += n;
  }
  return area_n;
}

// The keys as the scene's vertices (and uvs, when the mesh or the scene has them), placed by M.
void add_vertices(Scene& scene, const ObjText& obj, const Faces& faces, const glm::dmat4& M,
                  bool textured) {
  const std::vector<glm::dvec3> area_n = area_normals(obj, faces);
  const bool identity = M == glm::dmat4(1.0);
  const glm::dmat3 N = glm::transpose(glm::inverse(glm::dmat3(M)));
  if (textured || !scene.uvs.empty()) scene.uvs.resize(scene.vertices.size(), glm::vec2(0));
  scene.vertices.reserve(scene.vertices.size() + faces.keys.size());
  for (const auto& k : faces.keys) {
    glm::dvec3 n = file_normal(obj, k);
    if (!(glm::length(n) > 0)) n = area_n[std::size_t(k.v)];
    Vertex v;
    glm::dvec3 p = position(obj, k.v);
    if (!identity) {
      p = glm::dvec3(M * glm::dvec4(p, 1.0));
      n = N * n;
    }
    double len = glm::length(n);
    v.position = glm::vec3(p);
    v.normal = len > 0 ? glm::vec3(n / len) : glm::vec3(0, 0, 1);
    scene.vertices.push_back(v);
    if (textured || !scene.uvs.empty()) {
      glm::vec2 uv(0);
      if (k.t >= 0 && 2 * std::size_t(k.t) + 1 < obj.texcoords.size())
        uv =
            glm::vec2(obj.texcoords[2 * std::size_t(k.t)], obj.texcoords[2 * std::size_t(k.t) + 1]);
      scene.uvs.push_back(uv);
    }
  }
}

// How the scene's object list describes the mesh.
std::string mesh_text(const std::string& path, const glm::dmat4& M, std::uint32_t default_material,
                      bool flip_winding) {
  std::string text = "mesh";
  if (M != glm::dmat4(1.0)) {
    text += " matrix ";
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        text += text::fmt(M[c][r]) + (c == 3 && r == 3 ? "" : ",");
  }
  text += " mat " + std::to_string(default_material);
  if (flip_winding) text += " flip";
  return text + " file " + path;
}

} // namespace

void append_obj(Scene& scene, const std::string& path, const ObjectTransform& xf,
                std::uint32_t default_material, bool flip_winding) {
  std::map<std::string, TexRef> textures; // by material name, from every mtllib
  const ObjText obj = read_checked_obj(path, textures);
  std::vector<tinyobj::material_t> mats;
  const std::vector<int> segment_material = segment_materials(path, obj, mats);
  const std::uint32_t mat_base = std::uint32_t(scene.materials.size());
  const std::vector<bool> mat_textured = add_materials(scene, mats, textures);
  std::vector<int> face_materials(obj.face_size.size());
  bool textured = false;
  for (std::size_t f = 0; f < obj.face_size.size(); ++f) {
    const int id = face_materials[f] = segment_material[obj.face_segment[f]];
    if (id >= 0 && std::size_t(id) < mats.size() && mat_textured[std::size_t(id)]) textured = true;
  }
  Faces faces = make_faces(obj, face_materials, mats.size(), textured, mat_base, default_material,
                           flip_winding);
  std::vector<Triangle>& tris = faces.tris;
  if (scene.triangles.size() + tris.size() > scene.triangle_budget)
    throw InputError(path, 0,
                     std::to_string(tris.size()) + " triangles would take the scene to " +
                         std::to_string(scene.triangles.size() + tris.size()) +
                         ", over its budget of " + std::to_string(scene.triangle_budget));

  const glm::dmat4 M = xf.to_matrix();
  ObjectDesc d;
  d.kind = "mesh";
  d.first_vertex = std::uint32_t(scene.vertices.size());
  d.first_triangle = std::uint32_t(scene.triangles.size());
  add_vertices(scene, obj, faces, M, textured);
  const bool flip = glm::determinant(glm::dmat3(M)) < 0;
  for (auto& t : tris) {
    for (auto& v : t.v)
      v += d.first_vertex;
    if (flip) std::swap(t.v[1], t.v[2]);
  }
  scene.triangles.insert(scene.triangles.end(), tris.begin(), tris.end());
  d.vertex_count = std::uint32_t(faces.keys.size());
  d.triangle_count = std::uint32_t(tris.size());
  d.text = mesh_text(path, M, default_material, flip_winding);
  scene.objects.push_back(std::move(d));
}

} // namespace zc
