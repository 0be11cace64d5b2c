#pragma once
// "WxH" image sizes on the command line.
#include <string>

namespace zc {

// Largest image side accepted (each side); a bigger request is an input error, not an allocation.
constexpr int kMaxImageSide = 16384;

struct ImageSize {
  int width = 0, height = 0;
};

// Parses "640x480" (or "640" for a square); throws UsageError naming the flag on anything else,
// including 0 and sides above kMaxImageSide.
ImageSize parse_image_size(const std::string& text, const std::string& flag = "--size");

} // namespace zc
