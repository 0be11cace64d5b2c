#pragma once
// Named colours for Blazek's scene language ("color red", "background black", "overlay gray") and
// the JSON scene format, and seeded random colours ("color random").
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "scene/prng.hpp"

namespace zc {

std::optional<glm::vec3> named_color(const std::string& name);

// A random colour on a 1/255 grid (what an 8-bit frame buffer of 1991 could show).
inline glm::vec3 random_color(SplitMix64& g) {
  glm::vec3 c;
  for (int k = 0; k < 3; ++k)
    c[k] = float(g.next() >> 56) / 255.0f;
  return c;
}

} // namespace zc
