// Blazek's flat scene description language (thesis ch. IV "Scene Description Language", Figure 9):
// one definition per line, '#' comments, no order imposed. A definition is a viewer/view-plane
// parameter or "obj <kind>" followed by (parameter, value) tuples.
//
// Figure 9's keywords, and how zcube reads them:
//   ambient N        ambient light level; N > 1 is a percentage (40 -> 0.40), else a fraction
//   background C     background colour (a name, or r,g,b in 0..1)
//   light x,y,z      a directional light shining from x,y,z towards the origin (one per line)
//   nodes N          accepted and ignored: the node count is the simulator's --nodes
//   overlay C        accepted and ignored: the thesis does not define it (probably a display
//                    overlay on the SUN's HIP viewer); nothing in the image depends on it
//   outfile NAME     accepted and ignored: the output file is the CLI's --image
//   percent N        accepted and ignored: undefined in the thesis (plausibly the share of
//                    background pixels made stars, "a field of multicolored stars"); zcube draws
//                    no stars, so every method renders the same background
// zcube's additions (the thesis's viewer position/direction have no keyword in Figure 9):
//   eye x,y,z  target x,y,z  up x,y,z  fov DEG  size WxH  cull none|back  seed N
// Object parameters: rot x,y,z (radians, as a 1991 C program would pass to sin/cos), scale s or
//   sx,sy,sz, num N (copies), color NAME|random|r,g,b, recursion R, position x,y,z (without it
//   each copy is placed at random in [-1,1]^3), slices N, radii x,y,z, level L, file PATH.
#include "geometry/camera.hpp"
#include "scene/bezier.hpp"
#include "scene/colors.hpp"
#include "scene/loaders.hpp"
#include "scene/prng.hpp"
#include "scene/text.hpp"
#include "util/error.hpp"
#include "util/image_size.hpp"
#include "util/input_file.hpp"

#include <filesystem>
#include <numbers>

namespace zc {

namespace {

struct Sdl {
  std::string file;
  int line = 0;
  [[noreturn]] void fail(const std::string& why) const { throw InputError(file, line, why); }

  glm::dvec3 vec3(std::string_view s, const std::string& what) const {
    auto tok = text::split(s, true);
    if (tok.size() != 3) fail(what + " needs x,y,z");
    glm::dvec3 v;
    for (int k = 0; k < 3; ++k) {
      auto d = text::to_double(tok[std::size_t(k)]);
      if (!d) fail(what + ": not a finite number '" + std::string(tok[std::size_t(k)]) + "'");
      v[k] = *d;
    }
    return v;
  }
  double number(std::string_view s, const std::string& what) const {
    auto d = text::to_double(s);
    if (!d) fail(what + ": not a finite number '" + std::string(s) + "'");
    return *d;
  }
  long long integer(std::string_view s, const std::string& what, long long lo, long long hi) const {
    auto v = text::to_int(s);
    if (!v || *v < lo || *v > hi)
      fail(what + " must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
    return *v;
  }
  glm::vec3 color(std::string_view s, const std::string& what) const {
    if (auto c = named_color(std::string(s))) return *c;
    if (s.find(',') == std::string_view::npos)
      fail(what + ": unknown colour '" + std::string(s) + "'");
    glm::dvec3 c = vec3(s, what);
    for (int k = 0; k < 3; ++k)
      if (c[k] < 0 || c[k] > 1) fail(what + ": colour components must be in 0..1");
    return glm::vec3(c);
  }
};

struct PendingObject {
  int line = 0;
  std::vector<std::string_view> tok;
};

using Tokens = std::vector<std::string_view>;

// What the definitions other than objects leave for later: the objects, the viewer and the seed.
struct Definitions {
  std::vector<PendingObject> objects;
  bool have_camera = false;
  Camera cam;
  std::uint64_t seed = 1991;
};

// Requires exactly k values after the keyword.
void need_values(const Sdl& p, const std::string& key, const Tokens& tok, std::size_t k) {
  if (tok.size() != k + 1) p.fail("'" + key + "' takes " + std::to_string(k) + " value(s)");
}

// ambient, background, light; false for another keyword.
bool read_lighting(Scene& scene, const Sdl& p, const std::string& key, const Tokens& tok) {
  if (key == "ambient") {
    need_values(p, key, tok, 1);
    double a = p.number(tok[1], "ambient");
    if (a > 1) a /= 100.0; // Figure 9: "ambient 40" is a percentage
    if (a < 0 || a > 1) p.fail("ambient must be 0..1 or a percentage 0..100");
    scene.ambient = glm::vec3(float(a));
  } else if (key == "background") {
    need_values(p, key, tok, 1);
    scene.background = p.color(tok[1], "background");
  } else if (key == "light") {
    if (tok.size() < 2 || tok.size() > 3) p.fail("light takes x,y,z [colour]");
    glm::dvec3 from = p.vec3(tok[1], "light");
    if (glm::length(from) == 0) p.fail("light position must not be the origin");
    DirectionalLight dl;
    dl.direction = glm::vec3(-glm::normalize(from)); // travels from x,y,z towards the scene
    if (tok.size() == 3) dl.color = p.color(tok[2], "light colour");
    scene.lights.push_back(dl);
  } else {
    return false;
  }
  return true;
}

// Figure 9's keywords zcube checks and ignores; false for another keyword.
bool read_ignored(const Sdl& p, const std::string& key, const Tokens& tok) {
  if (key == "nodes") {
    need_values(p, key, tok, 1);
    p.integer(tok[1], "nodes", 1, 1 << 20); // checked, then left to the simulator's --nodes
  } else if (key == "overlay") {
    need_values(p, key, tok, 1);
    p.color(tok[1], "overlay");
  } else if (key == "outfile") {
    need_values(p, key, tok, 1);
  } else if (key == "percent") {
    need_values(p, key, tok, 1);
    double v = p.number(tok[1], "percent");
    if (v < 0 || v > 100) p.fail("percent must be in 0..100");
  } else {
    return false;
  }
  return true;
}

// zcube's viewer keywords: eye, target, up, fov, size, cull, seed; false for another keyword.
bool read_viewer(Scene& scene, const Sdl& p, const std::string& key, const Tokens& tok,
                 Definitions& d) {
  if (key == "eye" || key == "target" || key == "up") {
    need_values(p, key, tok, 1);
    glm::dvec3 v = p.vec3(tok[1], key);
    (key == "eye" ? d.cam.eye : key == "target" ? d.cam.target : d.cam.up) = v;
    d.have_camera = true;
  } else if (key == "fov") {
    need_values(p, key, tok, 1);
    d.cam.fovy_deg = p.number(tok[1], "fov");
    if (!(d.cam.fovy_deg > 0 && d.cam.fovy_deg < 180)) p.fail("fov must be in (0, 180) degrees");
    d.have_camera = true;
  } else if (key == "size") {
    need_values(p, key, tok, 1);
    std::string s = text::lower(tok[1]);
    auto x = s.find('x');
    if (x == std::string::npos) p.fail("size needs WxH");
    scene.width = int(p.integer(std::string_view(s).substr(0, x), "size width", 1, kMaxImageSide));
    scene.height =
        int(p.integer(std::string_view(s).substr(x + 1), "size height", 1, kMaxImageSide));
  } else if (key == "cull") {
    need_values(p, key, tok, 1);
    if (tok[1] == "none")
      scene.cull = CullMode::None;
    else if (tok[1] == "back")
      scene.cull = CullMode::Back;
    else
      p.fail("cull must be none or back");
  } else if (key == "seed") {
    need_values(p, key, tok, 1);
    d.seed = std::uint64_t(p.integer(tok[1], "seed", 0, 1ll << 53));
  } else {
    return false;
  }
  return true;
}

// Every line of the file read: the settings into the scene, the objects kept for later (their
// tokens view `src`).
Definitions read_definitions(Scene& scene, Sdl& p, const std::string& src) {
  Definitions d;
  std::size_t i = 0;
  int n = 0;
  while (i < src.size()) {
    std::size_t j = src.find('\n', i);
    if (j == std::string::npos) j = src.size();
    std::string_view l = std::string_view(src).substr(i, j - i);
    i = j + 1;
    p.line = ++n;
    if (auto h = l.find('#'); h != std::string_view::npos) l = l.substr(0, h);
    auto tok = text::split(l);
    if (tok.empty()) continue;
    const std::string key = text::lower(tok[0]);
    if (key == "obj") {
      if (tok.size() < 2) p.fail("obj needs a kind");
      d.objects.push_back({n, tok});
    } else if (!read_lighting(scene, p, key, tok) && !read_ignored(p, key, tok) &&
               !read_viewer(scene, p, key, tok, d)) {
      p.fail("unknown keyword '" + std::string(tok[0]) + "'");
    }
  }
  return d;
}

// An object line's parameters.
struct ObjectLine {
  ObjectSpec spec;
  long long num = 1;
  bool has_pos = false, random_colour = false, has_color = false;
  glm::vec3 color = glm::vec3(0.8f);
};

// One (parameter, value) of an object line into o; false for an unknown parameter.
bool read_object_parameter(const Sdl& p, const std::string& key, std::string_view v,
                           const std::string& path, ObjectLine& o) {
  ObjectSpec& spec = o.spec;
  if (key == "rot") {
    spec.xf.rotate_deg = p.vec3(v, "rot") * (180.0 / std::numbers::pi);
  } else if (key == "scale") {
    if (v.find(',') != std::string_view::npos)
      spec.xf.scale = p.vec3(v, "scale");
    else
      spec.xf.scale = glm::dvec3(p.number(v, "scale"));
  } else if (key == "num") {
    o.num = p.integer(v, "num", 1, 1 << 20);
  } else if (key == "color" || key == "colour") {
    o.has_color = true;
    if (text::lower(v) == "random")
      o.random_colour = true;
    else
      o.color = p.color(v, "color");
  } else if (key == "recursion") {
    spec.recursion = int(p.integer(v, "recursion", 0, kMaxRecursion));
  } else if (key == "position" || key == "pos") {
    spec.xf.translate = p.vec3(v, "position");
    o.has_pos = true;
  } else if (key == "slices") {
    spec.slices = int(p.integer(v, "slices", 3, kMaxSlices));
  } else if (key == "radii") {
    spec.radii = p.vec3(v, "radii");
    for (int q = 0; q < 3; ++q)
      if (!(spec.radii[q] > 0)) p.fail("radii must be positive");
  } else if (key == "level") {
    spec.level = int(p.integer(v, "level", 1, kMaxBezierLevel));
  } else if (key == "file") {
    spec.file = text::join_path(text::directory_of(path), std::string(v));
  } else {
    return false;
  }
  return true;
}

ObjectLine read_object(const Sdl& p, const PendingObject& ob, const std::string& path) {
  ObjectLine o;
  o.spec.kind = text::lower(ob.tok[1]);
  const std::string& k = o.spec.kind;
  if (k != "sphere" && k != "spheroid" && k != "cube" && k != "cone" && k != "cylinder" &&
      k != "bezier" && k != "mesh")
    p.fail("unknown object kind '" + std::string(ob.tok[1]) + "'");
  for (std::size_t t = 2; t < ob.tok.size(); t += 2) {
    const std::string key = text::lower(ob.tok[t]);
    if (t + 1 >= ob.tok.size()) p.fail("'" + key + "' needs a value");
    if (!read_object_parameter(p, key, ob.tok[t + 1], path, o))
      p.fail("unknown object parameter '" + std::string(ob.tok[t]) + "'");
  }
  if ((k == "bezier" || k == "mesh") && o.spec.file.empty()) p.fail(k + " needs a file");
  if (const auto bad = referenced_file_problem(k + " file", o.spec.file);
      !o.spec.file.empty() && !bad.empty())
    p.fail(bad);
  return o;
}

// The object's copies added to the scene, each from its own random stream (seed and line).
void add_copies(Scene& scene, const Sdl& p, const ObjectLine& o, std::uint64_t seed, int line) {
  const std::string& k = o.spec.kind;
  SplitMix64 g(mix_seed(seed, std::uint64_t(line)));
  try { // the budget, before the first copy is tessellated
    if (k != "mesh")
      check_triangle_budget(scene, std::uint64_t(o.num), triangle_count(o.spec),
                            (o.num > 1 ? std::to_string(o.num) + " x " : "") + "this " + k);
  } catch (const InputError& e) {
    if (e.file() == "<object>") p.fail(e.reason());
    throw;
  }
  for (long long c = 0; c < o.num; ++c) {
    ObjectSpec copy = o.spec;
    if (!o.has_pos) copy.xf.translate = {g.coord(-1, 1), g.coord(-1, 1), g.coord(-1, 1)};
    copy.color = o.random_colour ? random_color(g) : o.has_color ? o.color : scene.materials[0].kd;
    copy.material = o.has_color ? color_material(scene, copy.color) : 0;
    try {
      if (k == "mesh")
        append_obj(scene, copy.file, copy.xf, copy.material);
      else
        add_object(scene, copy);
    } catch (const InputError& e) {
      if (e.file() == "<object>") p.fail(e.reason());
      throw;
    }
  }
}

} // namespace

void load_sdl_scene(Scene& scene, const std::string& path) {
  const std::string src = text::read_file(path);
  Sdl p{path};
  const Definitions d = read_definitions(scene, p, src);
  if (scene.lights.empty()) {
    DirectionalLight dl;
    dl.direction = glm::normalize(glm::vec3(1, -1, -1));
    scene.lights.push_back(dl);
  }
  // Objects after the viewer definitions ("no order is imposed"), each from its own random stream.
  for (const auto& ob : d.objects) {
    p.line = ob.line;
    add_copies(scene, p, read_object(p, ob, path), d.seed, ob.line);
  }
  if (d.have_camera) {
    const Camera& cam = d.cam;
    if (glm::length(glm::cross(cam.target - cam.eye, cam.up)) == 0)
      throw InputError(path, 0, "eye, target and up do not define a view");
    scene.camera = cam;
  } else {
    scene.camera = framing_camera(scene_bounds(scene));
  }
}

} // namespace zc
