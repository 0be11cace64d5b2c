#pragma once
// Writing images (OpenImageIO) and fingerprinting them: the SHA-256 of the RGB8 pixels is what
// reports and regression tests compare, so it ignores file-format details.
#include <string>
#include <vector>

#include "raster/framebuffer.hpp"

namespace zc {

// Writes the colour of a full-screen frame buffer as PNG (or any format OIIO knows by extension).
void write_png(const Framebuffer& fb, const std::string& path);
// The depth map --depth writes: each pixel's depth, 1.0 (the far plane) where no triangle is.
std::vector<float> depth_map(const Framebuffer& fb);
// depth_map(fb) == map, without making the depth map (a megabyte of fresh memory a picture).
bool same_depth_map(const Framebuffer& fb, const std::vector<float>& map);
// Writes the depth map as a single-channel float EXR.
void write_depth_exr(const Framebuffer& fb, const std::string& path);
// Hex SHA-256 of width, height and the RGB8 pixels, rows top to bottom.
std::string image_sha256(const Framebuffer& fb);

} // namespace zc
