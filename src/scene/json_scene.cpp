// The JSON scene format (documented in scenes/README.md): image, background, ambient, lights,
// camera, culling, texture filter, and objects (meshes, Newell Bezier patches, Blazek's primitives)
// with transforms, colours and seeded replication.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "geometry/camera.hpp"
#include "scene/bezier.hpp"
#include "scene/colors.hpp"
#include "scene/loaders.hpp"
#include "scene/prng.hpp"
#include "scene/text.hpp"
#include "util/error.hpp"
#include "util/image_size.hpp"
#include "util/input_file.hpp"

namespace zc {

namespace {

using json = nlohmann::json;

struct Ctx {
  std::string file;
  std::string dir;
  [[noreturn]] void fail(const std::string& where, const std::string& why) const {
    throw InputError(file, 0, where + ": " + why);
  }
  double number(const json& j, const std::string& where) const {
    if (!j.is_number()) fail(where, "expected a number");
    double v = j.get<double>();
    if (!std::isfinite(v)) fail(where, "not a finite number");
    return v;
  }
  long long integer(const json& j, const std::string& where, long long lo, long long hi) const {
    if (!j.is_number()) fail(where, "expected an integer");
    double v = j.get<double>();
    if (!(v >= double(lo) && v <= double(hi)) || v != std::floor(v))
      fail(where, "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
    return (long long)v;
  }
  glm::dvec3 vec3(const json& j, const std::string& where) const {
    if (!j.is_array() || j.size() != 3) fail(where, "expected [x, y, z]");
    return {number(j[0], where + "[0]"), number(j[1], where + "[1]"), number(j[2], where + "[2]")};
  }
  std::string string(const json& j, const std::string& where) const {
    if (!j.is_string()) fail(where, "expected a string");
    return j.get<std::string>();
  }
  // [r,g,b] in 0..1, a name, or (when allowed) "random".
  glm::vec3 color(const json& j, const std::string& where) const {
    if (j.is_string()) {
      auto c = named_color(j.get<std::string>());
      if (!c) fail(where, "unknown colour '" + j.get<std::string>() + "'");
      return *c;
    }
    glm::dvec3 c = vec3(j, where);
    for (int k = 0; k < 3; ++k)
      if (c[k] < 0 || c[k] > 1) fail(where, "colour components must be in 0..1");
    return glm::vec3(c);
  }
};

void check_keys(const Ctx& cx, const json& j, const std::string& where,
                std::initializer_list<const char*> allowed) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool ok = false;
    for (const char* a : allowed)
      ok |= it.key() == a;
    if (!ok) cx.fail(where, "unknown key '" + it.key() + "'");
  }
}

ObjectTransform parse_transform(const Ctx& cx, const json& j, const std::string& where) {
  ObjectTransform xf;
  if (!j.is_object()) cx.fail(where, "expected an object");
  check_keys(cx, j, where, {"translate", "rotate", "scale", "matrix"});
  if (j.contains("translate")) xf.translate = cx.vec3(j["translate"], where + ".translate");
  if (j.contains("rotate")) xf.rotate_deg = cx.vec3(j["rotate"], where + ".rotate");
  if (j.contains("scale")) {
    const json& s = j["scale"];
    if (s.is_number())
      xf.scale = glm::dvec3(cx.number(s, where + ".scale"));
    else
      xf.scale = cx.vec3(s, where + ".scale");
  }
  if (j.contains("matrix")) {
    if (j.contains("rotate") || j.contains("scale")) cx.fail(where, "matrix excludes rotate/scale");
    const json& m = j["matrix"];
    if (!m.is_array() || m.size() != 4) cx.fail(where + ".matrix", "expected 4 rows of 4 numbers");
    for (int r = 0; r < 4; ++r) {
      if (!m[std::size_t(r)].is_array() || m[std::size_t(r)].size() != 4)
        cx.fail(where + ".matrix", "expected 4 rows of 4 numbers");
      for (int c = 0; c < 4; ++c) // rows as written; glm is column-major
        xf.matrix[c][r] = cx.number(m[std::size_t(r)][std::size_t(c)], where + ".matrix");
    }
    xf.has_matrix = true;
  }
  return xf;
}

// An object entry's shape: its type, file, tessellation and transform.
ObjectSpec parse_shape(const Ctx& cx, const json& o, const std::string& where) {
  if (!o.contains("type")) cx.fail(where, "missing 'type'");
  ObjectSpec spec;
  spec.kind = cx.string(o["type"], where + ".type");
  const std::string& k = spec.kind;
  if (k != "mesh" && k != "bezier" && k != "sphere" && k != "spheroid" && k != "cube" &&
      k != "cone" && k != "cylinder")
    cx.fail(where + ".type", "unknown object type '" + k + "'");
  if (k == "mesh" || k == "bezier") {
    if (!o.contains("file")) cx.fail(where, "'" + k + "' needs a 'file'");
    spec.file = text::join_path(cx.dir, cx.string(o["file"], where + ".file"));
    if (const auto p = referenced_file_problem(k + " file", spec.file); !p.empty())
      cx.fail(where + ".file", p);
  }
  if (o.contains("level"))
    spec.level = int(cx.integer(o["level"], where + ".level", 1, kMaxBezierLevel));
  if (o.contains("recursion"))
    spec.recursion = int(cx.integer(o["recursion"], where + ".recursion", 0, kMaxRecursion));
  if (o.contains("slices"))
    spec.slices = int(cx.integer(o["slices"], where + ".slices", 3, kMaxSlices));
  if (o.contains("radii")) {
    spec.radii = cx.vec3(o["radii"], where + ".radii");
    for (int q = 0; q < 3; ++q)
      if (!(spec.radii[q] > 0)) cx.fail(where + ".radii", "radii must be positive");
  }
  if (o.contains("transform")) spec.xf = parse_transform(cx, o["transform"], where + ".transform");
  return spec;
}

// An object entry's colour: none (the default material), one, or random a copy.
struct ObjectColour {
  bool random = false, given = false;
  glm::vec3 color = glm::vec3(0.8f);
};
ObjectColour parse_colour(const Ctx& cx, const json& o, const std::string& where) {
  ObjectColour c;
  if (o.contains("color") && o.contains("material"))
    cx.fail(where, "give 'color' or 'material', not both");
  if (o.contains("color")) {
    c.given = true;
    if (o["color"].is_string() && o["color"].get<std::string>() == "random")
      c.random = true;
    else
      c.color = cx.color(o["color"], where + ".color");
  }
  if (o.contains("material")) {
    const json& m = o["material"];
    if (!m.is_object()) cx.fail(where + ".material", "expected {\"kd\": [r, g, b]}");
    check_keys(cx, m, where + ".material", {"kd", "name"});
    if (!m.contains("kd")) cx.fail(where + ".material", "missing 'kd'");
    c.color = cx.color(m["kd"], where + ".material.kd");
    c.given = true;
  }
  return c;
}

// How an object entry's copies are made: how many, from which seed, where, which way round.
struct Copies {
  long long count = 1;
  std::uint64_t seed = 1;
  bool placed = false, flip = false;
  glm::dvec3 lo = glm::dvec3(-1), hi = glm::dvec3(1);
};
Copies parse_copies(const Ctx& cx, const json& o, const std::string& where,
                    const std::string& kind) {
  Copies c;
  if (o.contains("count")) c.count = cx.integer(o["count"], where + ".count", 1, 1 << 20);
  if (o.contains("seed"))
    c.seed = std::uint64_t(cx.integer(o["seed"], where + ".seed", 0, (1ll << 53)));
  c.placed = o.contains("placement");
  if (c.placed) {
    const json& p = o["placement"];
    if (!p.is_object()) cx.fail(where + ".placement", "expected {\"min\": [..], \"max\": [..]}");
    check_keys(cx, p, where + ".placement", {"min", "max"});
    if (p.contains("min")) c.lo = cx.vec3(p["min"], where + ".placement.min");
    if (p.contains("max")) c.hi = cx.vec3(p["max"], where + ".placement.max");
    for (int q = 0; q < 3; ++q)
      if (c.lo[q] > c.hi[q]) cx.fail(where + ".placement", "min must not exceed max");
  }
  if (o.contains("flip_winding")) {
    if (!o["flip_winding"].is_boolean()) cx.fail(where + ".flip_winding", "expected true or false");
    if (kind != "mesh") cx.fail(where + ".flip_winding", "only for meshes");
    c.flip = o["flip_winding"].get<bool>();
  }
  return c;
}

// The copies added to the scene. One random stream per object entry: x, y, z (when placed) then
// the colour (when random).
void add_copies(Scene& scene, const ObjectSpec& spec, const ObjectColour& colour, const Copies& n,
                std::size_t index) {
  const std::string& k = spec.kind;
  SplitMix64 g(mix_seed(n.seed, index));
  const glm::dvec3 base = spec.xf.translate;
  if (k != "mesh") // the budget, before the first copy is tessellated
    check_triangle_budget(scene, std::uint64_t(n.count), triangle_count(spec),
                          (n.count > 1 ? std::to_string(n.count) + " x " : "") + "this " + k);
  for (long long c = 0; c < n.count; ++c) {
    ObjectSpec copy = spec;
    if (n.placed || n.count > 1)
      copy.xf.translate = base + glm::dvec3(g.coord(n.lo.x, n.hi.x), g.coord(n.lo.y, n.hi.y),
                                            g.coord(n.lo.z, n.hi.z));
    glm::vec3 col = colour.random ? random_color(g) : colour.color;
    copy.color = col;
    copy.material = colour.given ? color_material(scene, col) : 0;
    if (!colour.given) copy.color = scene.materials[0].kd;
    if (k == "mesh")
      append_obj(scene, copy.file, copy.xf, copy.material, n.flip);
    else
      add_object(scene, copy);
  }
}

void parse_object(Scene& scene, const Ctx& cx, const json& j, std::size_t index) {
  const std::string where = "objects[" + std::to_string(index) + "]";
  json o = j.is_string() ? json{{"type", j}} : j;
  if (!o.is_object()) cx.fail(where, "expected an object or a type name");
  check_keys(cx, o, where,
             {"type", "file", "level", "recursion", "slices", "radii", "transform", "color",
              "material", "count", "seed", "placement", "name", "flip_winding"});
  const ObjectSpec spec = parse_shape(cx, o, where);
  const ObjectColour colour = parse_colour(cx, o, where);
  const Copies copies = parse_copies(cx, o, where, spec.kind);
  try {
    add_copies(scene, spec, colour, copies, index);
  } catch (const InputError& e) {
    if (e.file() == "<object>") cx.fail(where, e.reason());
    throw;
  }
}

// The file parsed as JSON; a syntax error or a number beyond a double's range is an InputError
// with its line.
json parse_json(const std::string& path, const std::string& src) {
  try {
    return json::parse(src);
  } catch (const json::parse_error& e) {
    int line = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < src.size(); ++i)
      line += src[i] == '\n';
    std::string why = e.what();
    if (auto p = why.find("] "); p != std::string::npos) why = why.substr(p + 2);
    if (auto p = why.find(": "); p != std::string::npos && why.rfind("parse error", 0) == 0)
      why = "JSON " + why.substr(p + 2);
    throw InputError(path, line, why);
  } catch (const json::out_of_range& e) {
    // "number overflow parsing '1e400'": no byte offset, so the line is where the number is.
    std::string why = e.what(), num;
    if (auto p = why.find("] "); p != std::string::npos) why = why.substr(p + 2);
    if (auto a = why.find('\''), b = why.rfind('\''); a != std::string::npos && b > a)
      num = why.substr(a + 1, b - a - 1);
    const std::size_t at = num.empty() ? std::string::npos : src.find(num);
    const int line = at == std::string::npos
                         ? 0
                         : 1 + int(std::count(src.begin(), src.begin() + long(at), '\n'));
    throw InputError(path, line, "JSON " + why + " (beyond the range of a double)");
  }
}

// image, background, ambient.
void parse_image(Scene& scene, const Ctx& cx, const json& j) {
  if (j.contains("image")) {
    const json& im = j["image"];
    if (!im.is_object()) cx.fail("image", "expected {\"width\": W, \"height\": H}");
    check_keys(cx, im, "image", {"width", "height"});
    if (im.contains("width"))
      scene.width = int(cx.integer(im["width"], "image.width", 1, kMaxImageSide));
    if (im.contains("height"))
      scene.height = int(cx.integer(im["height"], "image.height", 1, kMaxImageSide));
  }
  if (j.contains("background")) scene.background = cx.color(j["background"], "background");
  if (j.contains("ambient")) {
    if (j["ambient"].is_number()) {
      double a = cx.number(j["ambient"], "ambient");
      if (a < 0 || a > 1) cx.fail("ambient", "must be in 0..1");
      scene.ambient = glm::vec3(float(a));
    } else {
      scene.ambient = cx.color(j["ambient"], "ambient");
    }
  }
}

// The lights, or by default one white light from the upper left.
void parse_lights(Scene& scene, const Ctx& cx, const json& j) {
  if (!j.contains("lights")) {
    DirectionalLight dl;
    dl.direction = glm::normalize(glm::vec3(1, -1, -1));
    scene.lights.push_back(dl);
    return;
  }
  if (!j["lights"].is_array()) cx.fail("lights", "expected an array");
  for (std::size_t i = 0; i < j["lights"].size(); ++i) {
    const json& l = j["lights"][i];
    const std::string w = "lights[" + std::to_string(i) + "]";
    if (!l.is_object()) cx.fail(w, "expected {\"direction\": [..], \"color\": [..]}");
    check_keys(cx, l, w, {"direction", "color"});
    DirectionalLight dl;
    if (!l.contains("direction")) cx.fail(w, "missing 'direction'");
    glm::dvec3 d = cx.vec3(l["direction"], w + ".direction");
    if (glm::length(d) == 0) cx.fail(w + ".direction", "must not be zero");
    dl.direction = glm::vec3(glm::normalize(d));
    if (l.contains("color")) dl.color = cx.color(l["color"], w + ".color");
    scene.lights.push_back(dl);
  }
}

// cull, texture_filter.
void parse_render_options(Scene& scene, const Ctx& cx, const json& j) {
  if (j.contains("cull")) {
    std::string c = cx.string(j["cull"], "cull");
    if (c == "none")
      scene.cull = CullMode::None;
    else if (c == "back")
      scene.cull = CullMode::Back;
    else
      cx.fail("cull", "expected \"none\" or \"back\"");
  }
  if (j.contains("texture_filter")) {
    std::string f = cx.string(j["texture_filter"], "texture_filter");
    if (f == "nearest")
      scene.filter = TextureFilter::Nearest;
    else if (f == "bilinear")
      scene.filter = TextureFilter::Bilinear;
    else
      cx.fail("texture_filter", "expected \"nearest\" or \"bilinear\"");
  }
}

Camera parse_camera(const Ctx& cx, const json& c) {
  if (!c.is_object()) cx.fail("camera", "expected an object");
  check_keys(cx, c, "camera", {"eye", "target", "up", "fov", "near", "far"});
  Camera cam;
  if (c.contains("eye")) cam.eye = cx.vec3(c["eye"], "camera.eye");
  if (c.contains("target")) cam.target = cx.vec3(c["target"], "camera.target");
  if (c.contains("up")) cam.up = cx.vec3(c["up"], "camera.up");
  if (c.contains("fov")) cam.fovy_deg = cx.number(c["fov"], "camera.fov");
  if (c.contains("near")) cam.znear = cx.number(c["near"], "camera.near");
  if (c.contains("far")) cam.zfar = cx.number(c["far"], "camera.far");
  if (!(cam.fovy_deg > 0 && cam.fovy_deg < 180))
    cx.fail("camera.fov", "must be in (0, 180) degrees");
  if (glm::length(cam.target - cam.eye) == 0) cx.fail("camera", "eye and target coincide");
  if (glm::length(cam.up) == 0) cx.fail("camera.up", "the zero vector (no direction)");
  if (glm::length(glm::cross(cam.target - cam.eye, cam.up)) == 0)
    cx.fail("camera.up", "parallel to the view direction");
  if (cam.znear < 0 || cam.zfar < 0 || (cam.znear > 0 && cam.zfar > 0 && cam.zfar <= cam.znear))
    cx.fail("camera", "need 0 < near < far");
  return cam;
}

} // namespace

void load_json_scene(Scene& scene, const std::string& path) {
  const std::string src = text::read_file(path);
  Ctx cx{path, text::directory_of(path)};
  const json j = parse_json(path, src);
  if (!j.is_object()) cx.fail("scene", "expected a JSON object");
  check_keys(cx, j, "scene",
             {"image", "background", "ambient", "lights", "camera", "cull", "texture_filter",
              "objects", "comment", "description"});
  parse_image(scene, cx, j);
  parse_lights(scene, cx, j);
  parse_render_options(scene, cx, j);
  // An empty array is a legal, empty scene (the background only).
  if (!j.contains("objects") || !j["objects"].is_array()) cx.fail("objects", "expected an array");
  for (std::size_t i = 0; i < j["objects"].size(); ++i)
    parse_object(scene, cx, j["objects"][i], i);
  scene.camera =
      j.contains("camera") ? parse_camera(cx, j["camera"]) : framing_camera(scene_bounds(scene));
}

} // namespace zc
