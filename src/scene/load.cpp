// load_scene: one entry point for every input format (see load.hpp), dispatching by extension and,
// for extension-less files, by content (Newell's "teapot" file is a patch file; anything else is
// read as Blazek's scene description language).
#include "scene/load.hpp"

#include <filesystem>

#include "geometry/camera.hpp"
#include "scene/bezier.hpp"
#include "scene/loaders.hpp"
#include "scene/scene_range.hpp"
#include "scene/text.hpp"
#include "util/error.hpp"
#include "util/image_size.hpp"
#include "util/input_file.hpp"

namespace zc {

void finish_uvs(Scene& scene) {
  if (scene.textures.empty()) {
    scene.uvs.clear();
    scene.uvs.shrink_to_fit();
  } else {
    scene.uvs.resize(scene.vertices.size(), glm::vec2(0));
  }
}

namespace {

void bare_defaults(Scene& s) {
  DirectionalLight l;
  l.direction = glm::normalize(glm::vec3(1, -1, -1)); // from the upper left, behind the viewer
  s.lights = {l};
  s.camera = framing_camera(scene_bounds(s));
}

} // namespace

Scene load_scene(const std::string& path, const LoadOptions& opt) {
  check_input_file(path);
  Scene s;
  s.path = path;
  s.triangle_budget = opt.max_triangles;
  const std::string ext = text::lower(std::filesystem::path(path).extension().string());
  const bool is_json = ext == ".json";
  if (is_json) {
    load_json_scene(s, path);
  } else if (ext == ".obj") {
    append_obj(s, path, ObjectTransform{}, 0);
    bare_defaults(s);
  } else if (ext == ".bpt" || looks_like_bezier(text::read_file(path))) {
    ObjectSpec b;
    b.kind = "bezier";
    b.file = path;
    b.xf.rotate_deg = {-90, 0, 0}; // Newell's data is z-up; zcube's default camera is y-up
    add_object(s, b);
    bare_defaults(s);
  } else {
    load_sdl_scene(s, path);
  }
  finish_uvs(s);
  if (opt.width > 0) s.width = opt.width;
  if (opt.height > 0) s.height = opt.height;
  if (s.width < 1 || s.height < 1 || s.width > kMaxImageSide || s.height > kMaxImageSide)
    throw InputError(path, 0,
                     "image size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                         " out of range (each side 1.." + std::to_string(kMaxImageSide) + ")");
  // A JSON scene may say "objects": [] on purpose (an empty scene renders the background); a mesh
  // or scene file without a single triangle is more likely a mistake.
  if (s.triangles.empty() && !is_json) throw InputError(path, 0, "the scene has no triangles");
  check_numeric_range(s);
  return s;
}

} // namespace zc
