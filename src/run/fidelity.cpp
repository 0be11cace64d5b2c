#include "run/fidelity.hpp"

#include "util/error.hpp"

namespace zc {

Fidelity parse_fidelity(const std::string& s) {
  if (s == "analytic") return Fidelity::Analytic;
  if (s == "flow") return Fidelity::Flow;
  if (s == "circuit") return Fidelity::Circuit;
  throw UsageError("--fidelity '" + s + "': expected analytic, flow or circuit");
}

const char* fidelity_name(Fidelity f) {
  switch (f) {
  case Fidelity::Analytic:
    return "analytic";
  case Fidelity::Flow:
    return "flow";
  default:
    return "circuit";
  }
}

} // namespace zc
