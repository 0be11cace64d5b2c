#include "raster/counters.hpp"

#include <nlohmann/json.hpp>

namespace zc {

#define ZC_COUNTER_FIELDS(X)                                                                       \
  X(vertices_transformed)                                                                          \
  X(triangles_in)                                                                                  \
  X(triangles_culled)                                                                              \
  X(triangles_clipped)                                                                             \
  X(triangles_setup)                                                                               \
  X(spans)                                                                                         \
  X(pixels_generated)                                                                              \
  X(pixels_tested)                                                                                 \
  X(pixels_written)                                                                                \
  X(pixels_final)                                                                                  \
  X(texels_fetched)                                                                                \
  X(pixels_cleared)                                                                                \
  X(merge_ops)                                                                                     \
  X(bytes_packed)

Counters& Counters::operator+=(const Counters& o) {
#define ZC_ADD(f) f += o.f;
  ZC_COUNTER_FIELDS(ZC_ADD)
#undef ZC_ADD
  return *this;
}

Counters Counters::operator-(const Counters& o) const {
  Counters r = *this;
#define ZC_SUB(f) r.f -= o.f;
  ZC_COUNTER_FIELDS(ZC_SUB)
#undef ZC_SUB
  return r;
}

void to_json(nlohmann::json& j, const Counters& c) {
  j = nlohmann::json::object();
#define ZC_JSON(f) j[#f] = c.f;
  ZC_COUNTER_FIELDS(ZC_JSON)
#undef ZC_JSON
}

} // namespace zc
