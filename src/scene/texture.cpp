// map_Kd textures through OpenImageIO, loaded on first use (util/image_module); Malerich 2017: the
// MTL holds the texture. Converted to RGB8 with rows top to bottom.
#include <filesystem>

#include "scene/loaders.hpp"
#include "util/error.hpp"
#include "util/image_module.hpp"
#include "util/input_file.hpp"

namespace zc {

Texture load_texture(const std::string& path, const std::string& ref_file, int ref_line) {
  if (const auto p = referenced_file_problem("texture file", path); !p.empty())
    throw InputError(ref_file, ref_line, p);
  image_module::Pixels px;
  std::string err;
  switch (image_module::read(path, px, err)) {
  case image_module::ReadStatus::Ok:
    break;
  case image_module::ReadStatus::CannotOpen:
    throw InputError(ref_file, ref_line, "cannot read texture " + path + ": " + err);
  case image_module::ReadStatus::UnusableSize:
    throw InputError(ref_file, ref_line, "texture " + path + " has an unusable size");
  default:
    throw InputError(ref_file, ref_line, "cannot decode texture " + path + ": " + err);
  }
  const int nc = px.channels;
  const std::vector<std::uint8_t>& raw = px.data;
  Texture t;
  t.path = path;
  t.width = px.width;
  t.height = px.height;
  const std::size_t n = std::size_t(t.width) * std::size_t(t.height);
  t.rgb.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      t.rgb[i * 3 + std::size_t(c)] = raw[i * std::size_t(nc) + std::size_t(nc >= 3 ? c : 0)];
  return t;
}

} // namespace zc
