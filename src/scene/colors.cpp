#include "scene/colors.hpp"

#include <map>

#include "scene/text.hpp"

namespace zc {

std::optional<glm::vec3> named_color(const std::string& name) {
  static const std::map<std::string, glm::vec3> table = {{"black", {0, 0, 0}},
                                                         {"white", {1, 1, 1}},
                                                         {"red", {1, 0, 0}},
                                                         {"green", {0, 1, 0}},
                                                         {"blue", {0, 0, 1}},
                                                         {"yellow", {1, 1, 0}},
                                                         {"cyan", {0, 1, 1}},
                                                         {"magenta", {1, 0, 1}},
                                                         {"gray", {0.5f, 0.5f, 0.5f}},
                                                         {"grey", {0.5f, 0.5f, 0.5f}},
                                                         {"orange", {1, 0.5f, 0}},
                                                         {"purple", {0.5f, 0, 0.5f}},
                                                         {"brown", {0.6f, 0.3f, 0.1f}},
                                                         {"pink", {1, 0.75f, 0.8f}},
                                                         {"ivory", {1, 1, 0.94f}},
                                                         {"bone", {0.89f, 0.85f, 0.79f}}};
  auto it = table.find(text::lower(name));
  if (it == table.end()) return std::nullopt;
  return it->second;
}

} // namespace zc
