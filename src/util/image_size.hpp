#pragma once
// "WxH" image sizes on the command line.
#include <string>

namespace zc {

struct ImageSize {
  int width = 0, height = 0;
};

// Parses "640x480" (or "640" for a square); throws UsageError naming the flag on anything else,
// including 0 and sides above kMaxImageSide.
ImageSize parse_image_size(const std::string& text, const std::string& flag = "--size");

} // namespace zc
