// map_Kd textures through OpenImageIO (Malerich 2017: the MTL holds the texture), converted to
// RGB8 with rows top to bottom.
#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "scene/loaders.hpp"
#include "util/error.hpp"

namespace zc {

Texture load_texture(const std::string& path, const std::string& ref_file, int ref_line) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(ref_file, ref_line, "texture file not found: " + path);
  auto in = OIIO::ImageInput::open(path);
  if (!in)
    throw InputError(ref_file, ref_line, "cannot read texture " + path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.width > 65536 ||
      spec.height > 65536)
    throw InputError(ref_file, ref_line, "texture " + path + " has an unusable size");
  const int nc = spec.nchannels;
  std::vector<std::uint8_t> raw(std::size_t(spec.width) * std::size_t(spec.height) *
                                std::size_t(nc));
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::UINT8, raw.data())) {
    std::string err = in->geterror();
    throw InputError(ref_file, ref_line, "cannot decode texture " + path + ": " + err);
  }
  Texture t;
  t.path = path;
  t.width = spec.width;
  t.height = spec.height;
  const std::size_t n = std::size_t(t.width) * std::size_t(t.height);
  t.rgb.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      t.rgb[i * 3 + std::size_t(c)] = raw[i * std::size_t(nc) + std::size_t(nc >= 3 ? c : 0)];
  return t;
}

} // namespace zc
