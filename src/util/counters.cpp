#include "util/counters.hpp"

#include <nlohmann/json.hpp>

namespace zc {

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

nlohmann::json nonzero_json(const Counters& c) {
  nlohmann::json j = nlohmann::json::object();
#define ZC_JSON(f)                                                                                 \
  if (c.f != 0) j[#f] = c.f;
  ZC_COUNTER_FIELDS(ZC_JSON)
#undef ZC_JSON
  return j;
}

void from_json(const nlohmann::json& j, Counters& c) {
  c = Counters{};
#define ZC_FROM_JSON(f)                                                                            \
  if (j.contains(#f)) c.f = j.at(#f).get<std::uint64_t>();
  ZC_COUNTER_FIELDS(ZC_FROM_JSON)
#undef ZC_FROM_JSON
}

} // namespace zc
