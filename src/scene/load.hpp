#pragma once
// Scene loading: one entry point for every input format zcube reads.
//   *.json            JSON scene (camera, image, lights, objects: meshes, Bezier patches,
//   primitives)
//   *.obj             bare mesh (with its MTL and map_Kd textures), framed by a default camera
//   *.bpt, teaset     Newell Bezier patches, framed by a default camera
//   anything else     Blazek's flat scene description language (thesis ch. IV, Figure 9)
// Every malformed input throws zc::InputError naming file, line and reason.
#include <cstdint>
#include <string>

#include "scene/scene.hpp"

namespace zc {

struct LoadOptions {
  int width = 0; // > 0 overrides the scene's image size
  int height = 0;
  std::uint64_t max_triangles = kMaxSceneTriangles; // more fails with an InputError
};

Scene load_scene(const std::string& path, const LoadOptions& opt = {});

} // namespace zc
