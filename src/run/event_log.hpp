#pragma once
// What happened when, on one node (or the host computer): the timeline behind the report's totals.
// Backend-neutral: the simulator fills it with virtual times, the MPI backend with measured ones.
// It exists only when a timeline is asked for (NodeStats::log is null otherwise), so an untraced
// run stores no event.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "machine/topology.hpp"

namespace zc {

// What a node does over an interval: compute (charged work), send (blocked until its message has
// gone) or wait (blocked in a receive). The rest of the run is idle.
enum class Activity : std::uint8_t { Compute, Send, Wait };
const char* activity_name(Activity a);

struct PhaseSpan {
  std::string name;
  int depth; // 0 outermost
  double begin_s, end_s;
};
struct ActivitySpan {
  Activity kind;
  double begin_s, end_s;
};
struct SendEvent {
  int dst, tag;
  std::uint64_t bytes;
  int hops; // channels of the route (host computer <-> node 0 counts one)
  double start_s;
};
struct RecvEvent {
  int src, tag;
  double arrival_s, done_s; // the message reached the node; the receive returned
};

struct EventLog {
  std::vector<PhaseSpan> phases; // in the order they ended
  std::vector<ActivitySpan> activities;
  std::vector<SendEvent> sends;
  std::vector<RecvEvent> recvs;

  // Adds an activity; one that continues the previous one of its kind without a gap extends it.
  void activity(Activity kind, double begin_s, double end_s);
};
void to_json(nlohmann::json& j, const EventLog& log);
void from_json(const nlohmann::json& j, EventLog& log);

// Channels a message crosses between ranks 0..P (P is the host computer, linked to node 0).
int message_hops(Topology t, int nodes, int src, int dst);

// The report's "timeline" section from the nodes' logs (nodes in rank order, then the host):
// "nodes": per node its phases and activities; "messages": every send matched with its receive
// (the k-th send from s to d with tag t is the k-th receive at d from s with tag t, as the Comm
// layer delivers in order); arrival and completion are null for a message never received.
nlohmann::json timeline_section(const std::vector<const EventLog*>& logs,
                                const std::vector<nlohmann::json>& ranks);

} // namespace zc
