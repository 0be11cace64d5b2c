#include "raster/shade.hpp"

#include <algorithm>

namespace zc {

static inline int wrap(int i, int n) {
  int m = i % n;
  return m < 0 ? m + n : m;
}

static inline glm::vec3 texel(const Texture& t, int x, int y) {
  const std::size_t i = 3 * (std::size_t(wrap(y, t.height)) * t.width + wrap(x, t.width));
  return glm::vec3(t.rgb[i], t.rgb[i + 1], t.rgb[i + 2]) * (1.0f / 255.0f);
}

glm::vec3 sample_texture(const Texture& t, float u, float v, TextureFilter f, Counters& c) {
  if (t.width <= 0 || t.height <= 0 || !std::isfinite(u) || !std::isfinite(v))
    return glm::vec3(1.0f);
  u -= std::floor(u);
  v -= std::floor(v);
  // Texture rows are stored top to bottom; v = 0 is the bottom of the image.
  const float fx = u * t.width - 0.5f;
  const float fy = (1.0f - v) * t.height - 0.5f;
  if (f == TextureFilter::Nearest) {
    ++c.texels_fetched;
    return texel(t, int(std::floor(fx + 0.5f)), int(std::floor(fy + 0.5f)));
  }
  c.texels_fetched += 4;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const float ax = fx - x0, ay = fy - y0;
  const glm::vec3 top = glm::mix(texel(t, x0, y0), texel(t, x0 + 1, y0), ax);
  const glm::vec3 bot = glm::mix(texel(t, x0, y0 + 1), texel(t, x0 + 1, y0 + 1), ax);
  return glm::mix(top, bot, ay);
}

} // namespace zc
