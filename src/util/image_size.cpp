#include "util/image_size.hpp"

#include <cstdlib>

#include "util/error.hpp"

namespace zc {

static int parse_side(const std::string& s, const std::string& flag, const std::string& text) {
  if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos)
    throw UsageError(flag + " '" + text + "': expected WxH with positive integers");
  const long v = std::strtol(s.c_str(), nullptr, 10);
  if (v <= 0 || v > kMaxImageSide)
    throw UsageError(flag + " '" + text + "': each side must be in 1.." +
                     std::to_string(kMaxImageSide));
  return int(v);
}

ImageSize parse_image_size(const std::string& text, const std::string& flag) {
  const auto x = text.find_first_of("xX");
  if (x == std::string::npos) {
    const int s = parse_side(text, flag, text);
    return {s, s};
  }
  return {parse_side(text.substr(0, x), flag, text), parse_side(text.substr(x + 1), flag, text)};
}

} // namespace zc
