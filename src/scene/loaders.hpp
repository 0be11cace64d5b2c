#pragma once
// Internal interface between load.cpp (dispatch, validation) and the format loaders.
#include <string>

#include "scene/load.hpp"
#include "scene/scene.hpp"
#include "scene/tessellate.hpp"

namespace zc {

// Appends an OBJ mesh (with its MTL materials and map_Kd textures) transformed by xf. Faces with no
// material get `default_material`. Records one ObjectDesc of kind "mesh".
// flip_winding reverses every face (for files wound clockwise, such as the misc3d teapot), so
// computed normals point the other way too.
void append_obj(Scene& scene, const std::string& path, const ObjectTransform& xf,
                std::uint32_t default_material, bool flip_winding = false);

// Loads a texture (RGB8, rows top to bottom) or throws InputError(file, line, ...) naming the
// place that referenced it.
Texture load_texture(const std::string& path, const std::string& ref_file, int ref_line);

void load_json_scene(Scene& scene, const std::string& path);
void load_sdl_scene(Scene& scene, const std::string& path);

// Makes uvs consistent (one per vertex when a texture is used, else empty) and frames a camera.
void finish_uvs(Scene& scene);

} // namespace zc
