// Wavefront OBJ + MTL through tinyobjloader (Malerich 2017: models come as .obj with a .mtl that
// holds the textures). tinyobjloader is lenient, so the text is checked first, line by line, and
// every fault becomes an InputError with its line number.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "scene/loaders.hpp"
#include "scene/text.hpp"
#include "util/error.hpp"

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

std::string_view keyword(std::string_view l) {
  std::size_t j = 0;
  while (j < l.size() && l[j] != ' ' && l[j] != '\t')
    ++j;
  return l.substr(0, j);
}

void need_numbers(const std::string& file, const Line& l, std::size_t min_count,
                  std::size_t max_count) {
  auto tok = text::split(l.text);
  if (tok.size() < min_count + 1)
    throw InputError(file, l.number,
                     "'" + std::string(tok[0]) + "' needs " + std::to_string(min_count) +
                         " numbers");
  for (std::size_t k = 1; k < tok.size() && k <= max_count; ++k)
    if (!text::to_float(tok[k]))
      throw InputError(file, l.number, "not a finite number: '" + std::string(tok[k]) + "'");
}

struct TexRef {
  std::string path, mtl; // texture file, and the MTL naming it at `line`
  int line = 0;
};

struct MtlInfo {
  std::map<std::string, TexRef> texture; // by material name
};

MtlInfo check_mtl(const std::string& path, const std::string& obj_file, int obj_line) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(obj_file, obj_line, "material library not found: " + path);
  const std::string s = text::read_file(path);
  MtlInfo info;
  std::string current;
  const std::string dir = text::directory_of(path);
  for_lines(s, [&](const Line& l) {
    std::string_view k = keyword(l.text);
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
      if (!std::filesystem::is_regular_file(tex, ec))
        throw InputError(path, l.number, "texture file not found: " + tex);
      info.texture[current] = TexRef{tex, path, l.number};
    }
  });
  return info;
}

struct ObjCheck {
  std::map<std::string, TexRef> texture;
  std::size_t faces = 0;
};

// Validates every line tinyobjloader would accept silently: numbers, face index ranges,
// the material library and its textures.
ObjCheck check_obj(const std::string& path, const std::string& s) {
  long long total[3] = {0, 0, 0}; // v, vt, vn
  for_lines(s, [&](const Line& l) {
    std::string_view k = keyword(l.text);
    if (k == "v")
      ++total[0];
    else if (k == "vt")
      ++total[1];
    else if (k == "vn")
      ++total[2];
  });
  ObjCheck out;
  long long seen[3] = {0, 0, 0};
  const std::string dir = text::directory_of(path);
  for_lines(s, [&](const Line& l) {
    std::string_view k = keyword(l.text);
    if (k == "v") {
      need_numbers(path, l, 3, 3);
      ++seen[0];
    } else if (k == "vt") {
      need_numbers(path, l, 1, 3);
      ++seen[1];
    } else if (k == "vn") {
      need_numbers(path, l, 3, 3);
      ++seen[2];
    } else if (k == "f") {
      auto tok = text::split(l.text);
      if (tok.size() < 4) throw InputError(path, l.number, "a face needs at least 3 vertices");
      if (tok.size() > 256) throw InputError(path, l.number, "a face has more than 255 vertices");
      for (std::size_t q = 1; q < tok.size(); ++q) {
        std::string_view ref = tok[q];
        if (ref.back() == '/' || std::count(ref.begin(), ref.end(), '/') > 2)
          throw InputError(path, l.number, "bad face vertex '" + std::string(ref) + "'");
        for (int part = 0; part < 3 && !ref.empty(); ++part) {
          std::size_t slash = ref.find('/');
          std::string_view num = ref.substr(0, slash);
          ref = slash == std::string_view::npos ? std::string_view() : ref.substr(slash + 1);
          if (num.empty() && part > 0) continue; // v//vn
          static const char* what[3] = {"vertex", "texture coordinate", "normal"};
          auto v = text::to_int(num);
          if (!v) throw InputError(path, l.number, "bad face vertex '" + std::string(tok[q]) + "'");
          long long idx = *v < 0 ? seen[part] + *v + 1 : *v;
          if (*v == 0 || idx < 1 || idx > total[part])
            throw InputError(path, l.number,
                             std::string(what[part]) + " index " + std::to_string(*v) +
                                 " out of range (the file has " + std::to_string(total[part]) +
                                 ")");
        }
      }
      ++out.faces;
    } else if (k == "mtllib") {
      auto tok = text::split(l.text);
      if (tok.size() < 2) throw InputError(path, l.number, "mtllib needs a file name");
      for (std::size_t q = 1; q < tok.size(); ++q) {
        MtlInfo m = check_mtl(text::join_path(dir, std::string(tok[q])), path, l.number);
        for (auto& [name, tex] : m.texture)
          out.texture[name] = tex;
      }
    } else if (k == "usemtl") {
      if (text::split(l.text).size() < 2) throw InputError(path, l.number, "usemtl needs a name");
    }
  });
  if (out.faces == 0) throw InputError(path, 0, "no faces");
  return out;
}

} // namespace

void append_obj(Scene& scene, const std::string& path, const ObjectTransform& xf,
                std::uint32_t default_material, bool flip_winding) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path, 0, "mesh file not found");
  std::string src = text::read_file(path);
  if (src.starts_with("\xEF\xBB\xBF")) src.erase(0, 3); // a UTF-8 byte-order mark
  ObjCheck check = check_obj(path, src);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> mats;
  std::string warn, err;
  const std::string dir = text::directory_of(path);
  // From the text already checked (without its byte-order mark), not from the file again.
  std::istringstream in(src);
  tinyobj::MaterialFileReader materials(dir.empty() ? std::string() : dir + "/");
  if (!tinyobj::LoadObj(&attrib, &shapes, &mats, &warn, &err, &in, &materials,
                        /*triangulate=*/false))
    throw InputError(path, 0, "cannot parse OBJ: " + std::string(text::trim(err)));
  for (float f : attrib.vertices)
    if (!std::isfinite(f)) throw InputError(path, 0, "non-finite vertex coordinate");

  // Materials: appended to the scene; textures loaded only where a material uses one.
  const std::uint32_t mat_base = std::uint32_t(scene.materials.size());
  std::vector<bool> mat_textured(mats.size(), false);
  for (std::size_t i = 0; i < mats.size(); ++i) {
    Material m;
    m.name = mats[i].name;
    m.kd = glm::vec3(mats[i].diffuse[0], mats[i].diffuse[1], mats[i].diffuse[2]);
    auto it = check.texture.find(mats[i].name);
    if (it != check.texture.end()) {
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
  bool textured = false;
  for (const auto& sh : shapes)
    for (int id : sh.mesh.material_ids)
      if (id >= 0 && std::size_t(id) < mats.size() && mat_textured[std::size_t(id)])
        textured = true;

  // Face-varying corners (v, vn, vt) become zcube vertices, first come first numbered; vt takes
  // part only when the mesh is textured (pay only for what is used).
  struct Key {
    int v, n, t;
    bool operator==(const Key& o) const { return v == o.v && n == o.n && t == o.t; }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      return std::size_t(k.v) * 0x9E3779B97F4A7C15ull ^
             std::size_t(k.n + 1) * 0xC2B2AE3D27D4EB4Full ^
             std::size_t(k.t + 1) * 0x165667B19E3779F9ull;
    }
  };
  std::unordered_map<Key, std::uint32_t, KeyHash> ids;
  std::vector<Key> keys;
  std::vector<Triangle> tris;
  tris.reserve(check.faces);
  for (const auto& sh : shapes) {
    std::size_t off = 0;
    for (std::size_t f = 0; f < sh.mesh.num_face_vertices.size(); ++f) {
      const std::size_t nv = sh.mesh.num_face_vertices[f];
      std::uint32_t corner[256];
      for (std::size_t c = 0; c < nv; ++c) {
        const auto& ix = sh.mesh.indices[off + c];
        Key k{ix.vertex_index, ix.normal_index, textured ? ix.texcoord_index : -1};
        auto [it, fresh] = ids.emplace(k, std::uint32_t(keys.size()));
        if (fresh) keys.push_back(k);
        corner[c] = it->second;
      }
      int mid = f < sh.mesh.material_ids.size() ? sh.mesh.material_ids[f] : -1;
      std::uint32_t mat = mid >= 0 && std::size_t(mid) < mats.size() ? mat_base + std::uint32_t(mid)
                                                                     : default_material;
      for (std::size_t c = 1; c + 1 < nv; ++c) { // a polygon becomes a fan around its first corner
        Triangle t;
        t.v[0] = corner[0];
        t.v[1] = corner[flip_winding ? c + 1 : c];
        t.v[2] = corner[flip_winding ? c : c + 1];
        t.material = mat;
        tris.push_back(t);
      }
      off += nv;
    }
  }

  // Area-weighted position normals for corners the file gives no normal.
  const std::size_t npos = attrib.vertices.size() / 3;
  auto pos = [&](int v) {
    return glm::dvec3(attrib.vertices[3 * std::size_t(v)], attrib.vertices[3 * std::size_t(v) + 1],
                      attrib.vertices[3 * std::size_t(v) + 2]);
  };
  std::vector<glm::dvec3> area_n;
  auto file_normal = [&](const Key& k) {
    if (k.n < 0 || 3 * std::size_t(k.n) + 2 >= attrib.normals.size()) return glm::dvec3(0);
    return glm::dvec3(attrib.normals[3 * std::size_t(k.n)],
                      attrib.normals[3 * std::size_t(k.n) + 1],
                      attrib.normals[3 * std::size_t(k.n) + 2]);
  };
  bool need_area = false; // some corner has no usable file normal
  for (const auto& k : keys)
    need_area |= !(glm::length(file_normal(k)) > 0);
  if (need_area) {
    area_n.assign(npos, glm::dvec3(0));
    for (const auto& t : tris) {
      const int a = keys[t.v[0]].v, b = keys[t.v[1]].v, c = keys[t.v[2]].v;
      glm::dvec3 n = glm::cross(pos(b) - pos(a), pos(c) - pos(a)); // |n| = 2 * area
      area_n[std::size_t(a)] += n;
      area_n[std::size_t(b)] += n;
      area_n[std::size_t(c)] += n;
    }
  }

  const glm::dmat4 M = xf.to_matrix();
  const bool identity = M == glm::dmat4(1.0);
  const glm::dmat3 N = glm::transpose(glm::inverse(glm::dmat3(M)));
  const bool flip = glm::determinant(glm::dmat3(M)) < 0;
  ObjectDesc d;
  d.kind = "mesh";
  d.first_vertex = std::uint32_t(scene.vertices.size());
  d.first_triangle = std::uint32_t(scene.triangles.size());
  if (textured || !scene.uvs.empty()) scene.uvs.resize(scene.vertices.size(), glm::vec2(0));
  scene.vertices.reserve(scene.vertices.size() + keys.size());
  for (const auto& k : keys) {
    glm::dvec3 n = file_normal(k);
    if (!(glm::length(n) > 0)) n = area_n[std::size_t(k.v)];
    Vertex v;
    glm::dvec3 p = pos(k.v);
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
      if (k.t >= 0 && 2 * std::size_t(k.t) + 1 < attrib.texcoords.size())
        uv = glm::vec2(attrib.texcoords[2 * std::size_t(k.t)],
                       attrib.texcoords[2 * std::size_t(k.t) + 1]);
      scene.uvs.push_back(uv);
    }
  }
  for (auto& t : tris) {
    for (auto& v : t.v)
      v += d.first_vertex;
    if (flip) std::swap(t.v[1], t.v[2]);
  }
  scene.triangles.insert(scene.triangles.end(), tris.begin(), tris.end());
  d.vertex_count = std::uint32_t(keys.size());
  d.triangle_count = std::uint32_t(tris.size());
  d.text = "mesh";
  if (!identity) {
    d.text += " matrix ";
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        d.text += text::fmt(M[c][r]) + (c == 3 && r == 3 ? "" : ",");
  }
  d.text += " mat " + std::to_string(default_material);
  if (flip_winding) d.text += " flip";
  d.text += " file " + path;
  scene.objects.push_back(std::move(d));
}

} // namespace zc
