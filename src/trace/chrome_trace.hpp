#pragma once
// The Chrome/Perfetto trace-event format (ui.perfetto.dev, chrome://tracing) of a timeline: one
// track (thread) per node and the host computer; phases as slices with compute, send, wait and idle
// nested in them; every received message a flow arrow from its send to its arrival carrying its
// bytes; and, per link of the interconnect, a counter of the messages in flight on it.
#include <nlohmann/json.hpp>

#include "trace/timeline.hpp"

namespace zc {

nlohmann::json chrome_trace(const Timeline& tl, const std::string& topology);

} // namespace zc
