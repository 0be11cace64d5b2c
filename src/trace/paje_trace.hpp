#pragma once
// The Paje trace format (Schnorr et al., the PajeNG tools: pj_dump, ViTE): containers for the
// machine, its nodes and host computer, and the links that carried messages; per node a "Phase"
// state (pushed and popped, so phases nest) and an "Activity" state (compute, send, wait, idle);
// every received message a Paje link from its sender to its receiver with its size in bytes; per
// link a variable counting the messages in flight.
#include <ostream>

#include "trace/timeline.hpp"

namespace zc {

void write_paje_trace(const Timeline& tl, const std::string& topology, std::ostream& out);

} // namespace zc
