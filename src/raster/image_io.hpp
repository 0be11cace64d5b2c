#pragma once
// Writing images (OpenImageIO) and fingerprinting them: the SHA-256 of the RGB8 pixels is what
// reports and regression tests compare, so it ignores file-format details.
#include <string>

#include "raster/framebuffer.hpp"

namespace zc {

// Writes the colour of a full-screen frame buffer as PNG (or any format OIIO knows by extension).
void write_png(const Framebuffer& fb, const std::string& path);
// Writes the depth as a single-channel float EXR; uncovered pixels get 1.0 (the far plane).
void write_depth_exr(const Framebuffer& fb, const std::string& path);
// Hex SHA-256 of width, height and the RGB8 pixels, rows top to bottom.
std::string image_sha256(const Framebuffer& fb);

} // namespace zc
