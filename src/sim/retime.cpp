#include "sim/retime.hpp"

#include "sim/retimer.hpp"

namespace zc {

std::string retimable(Fidelity fidelity, const NetworkParams& net) {
  if (fidelity == Fidelity::Flow) return "the flow fidelity shares links through SimGrid's solver";
  if (net.half_duplex_limited())
    return "links whose directions slow each other down (the T800's) are dated by the simulator";
  return "";
}

std::string retimable(const RetimeMachine& m) {
  if (std::string why = retimable(m.fidelity, m.net); !why.empty()) return why;
  return m.cost.empty() ? "no cost table" : "";
}

RetimedRun retime(const CallTrace& trace, const RetimeMachine& m, const ModelDraw& draw) {
  return retiming::Retimer(trace, m, draw).run();
}

} // namespace zc
