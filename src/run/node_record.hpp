#pragma once
// What one node recorded in a run, whatever the backend: its counters (NodeStats, updated by the
// backend's sends and charges), the pictures it handed over, and its NodeRecord at the end.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/framebuffer.hpp"
#include "run/event_log.hpp"
#include "util/counters.hpp"

namespace zc {

// What a node sent: the bytes the modelled machine is charged (its program's records, comm.hpp)
// and the bytes of zcube's payloads.
struct Traffic {
  std::uint64_t charged_bytes = 0, payload_bytes = 0, messages = 0;
  Traffic& operator+=(const Traffic& o) {
    charged_bytes += o.charged_bytes;
    payload_bytes += o.payload_bytes;
    messages += o.messages;
    return *this;
  }
};
void to_json(nlohmann::json& j, const Traffic& t);
void from_json(const nlohmann::json& j, Traffic& t);

// Counters of one node's run, whatever the backend.
// What every send, receive and charge updates comes first, in one host cache line: a simulation
// of many nodes switches between them at every message.
struct alignas(64) NodeStats {
  double busy_s = 0, comm_s = 0;
  std::uint64_t bytes_sent = 0, messages = 0; // bytes_sent: charged bytes
  std::uint64_t payload_bytes_sent = 0;
  // Bumped by every set_phase: a backend that keeps the current phase's phase_traffic entry
  // between sends checks this counter instead of comparing the name on every send.
  std::uint64_t phase_changes = 0;
  std::shared_ptr<EventLog> log; // the node's timeline; null unless one was asked for
  double finish_s = 0;
  std::string phase; // the innermost open phase ("" outside every phase); set by set_phase
  std::map<std::string, Traffic> phase_traffic; // what was sent in each phase
  double memory = 0, peak_memory = 0;
  bool timed = false;       // the node started the paper's timed region (start_timed_region)
  double timed_start_s = 0; // when
  bool timed_ended = false; // the node ended it (end_timed_region) before finishing
  double timed_end_s = 0;   // when
  // The end of the node's timed region: end_timed_region's time, else the node's finish.
  double timed_until_s() const { return timed_ended ? timed_end_s : finish_s; }
  void set_phase(const std::string& name) {
    phase = name;
    ++phase_changes;
  }
  // A send of `payload` bytes charged as `charged` (the backends call it).
  void count_send(std::size_t payload, std::size_t charged) {
    bytes_sent += charged;
    payload_bytes_sent += payload;
    ++messages;
    phase_traffic[phase] += Traffic{charged, payload, 1};
  }
};

// A picture (or, partial, rows of one) handed over by a node.
struct FrameImage {
  int frame;
  Framebuffer image;
  bool partial = false; // rows of the frame (deliver_rows), pasted together after the run
};

// Who recorded: node `rank`, or the host computer (Blazek's methods), which a report names by its
// platform host name.
struct Recorder {
  int rank = 0;
  bool host_computer = false;
  static Recorder node(int r) { return {r, false}; }
  static Recorder host(int nodes) { return {nodes, true}; }
};
// The report's "rank": the node's number, or "srm" for the host computer.
nlohmann::json rank_json(const Recorder& who);

// What one node (or the host computer) recorded.
struct NodeRecord {
  Recorder who;
  NodeStats stats;
  std::vector<std::string> phase_order;
  std::map<std::string, double> phase_totals;
  std::map<std::string, Counters> phase_work;
  Counters work;
  nlohmann::json metrics = nlohmann::json::object(); // the algorithm's own (NodeContext::metrics)
};
// The form a record travels in between processes (the MPI backend gathers them to rank 0).
void to_json(nlohmann::json& j, const NodeRecord& r);
void from_json(const nlohmann::json& j, NodeRecord& r);

} // namespace zc
