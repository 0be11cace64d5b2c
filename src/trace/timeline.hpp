#pragma once
// A report's "timeline" section (sim/event_log) read back for drawing and exporting: per node its
// phases, and its activities with the idle gaps filled in, so that every instant of the run is
// compute, send, wait or idle. The trace writers (Chrome/Perfetto, Paje) and tests share it.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace zc {

struct Span {
  std::string name; // phase name, or compute | send | wait | idle
  int depth = 0;    // phases: 0 outermost
  double begin_s = 0, end_s = 0;
};

struct NodeTimeline {
  int index;         // 0..P-1 the nodes, P the host computer
  std::string label; // "node 3", "host (srm)"
  std::vector<Span> phases;
  std::vector<Span> activities; // chronological; every slice split at phase boundaries
};

struct Timeline {
  int nodes = 0;      // P
  double total_s = 0; // the run's time
  std::string title;  // machine, algorithm, scene, P
  std::vector<NodeTimeline> tracks;
  nlohmann::json messages; // the report's timeline.messages
};

// Throws InputError when the report has no timeline (run without --trace/--gantt).
Timeline read_timeline(const nlohmann::json& report, const std::string& where);

} // namespace zc
