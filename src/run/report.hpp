#pragma once
// The report (docs/user-guide.md, "One run") from what each node recorded: shared by the SimGrid
// backend (virtual times) and any other backend (measured times), so both write the same schema.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/framebuffer.hpp"
#include "run/config.hpp"
#include "run/event_log.hpp"
#include "scene/scene.hpp"
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

// What one node (or the host computer, rank "srm") recorded.
struct NodeRecord {
  nlohmann::json rank; // int, or "srm"
  NodeStats stats;
  std::vector<std::string> phase_order;
  std::map<std::string, double> phase_totals;
  std::map<std::string, Counters> phase_work;
  Counters work;
  nlohmann::json metrics = nlohmann::json::object();
};
void to_json(nlohmann::json& j, const NodeRecord& r);
void from_json(const nlohmann::json& j, NodeRecord& r);

// The report's header: what ran where ("machine", "platform", "nodes", "topology", "fidelity",
// "algorithm", "options", "frames", "scene"), whatever the backend.
struct RunHeader {
  std::string machine, platform, topology, fidelity, scene_path;
  int nodes = 0;
};
void add_run_header(nlohmann::json& j, const RunHeader& h, const RunConfig& cfg,
                    const std::string& algorithm, const Scene& scene);

// "phases", "per_node", "communication", "counters", "load_imbalance" and the algorithm's metrics
// (node 0's, merged at the top level). `nodes` holds the P nodes in rank order, then the host if
// it ran; total_s is the run's time (for idle_s). With the nodes' event logs, also "timeline".
void add_node_sections(nlohmann::json& j, const std::vector<NodeRecord>& nodes, int P,
                       double total_s);

// What an image is compared with: the sequential renderer's picture of a scene at one frame of a
// run of `frames` frames, as its colour hash and its depth map.
struct ReferenceFrame {
  std::string sha256;
  std::vector<float> depth;
};
ReferenceFrame reference_frame(const Scene& scene, int frame, int frames);
// Where add_image_section finds a reference already drawn (by the process that forks a batch of
// simulations of the same scene, so that each draws it once): null when it has none, and then the
// image section draws it itself. The lookup is the process's (inherited by forked children).
using ReferenceLookup = std::function<const ReferenceFrame*(const Scene&, int frame, int frames)>;
void set_reference_lookup(ReferenceLookup lookup);

// "image": rows pasted into frames, hashes, and the comparison with the sequential renderer
// (when cfg.compare_with_sequential). The frames are moved to `out` in frame order.
void add_image_section(nlohmann::json& j, std::vector<FrameImage>& images, const Scene& scene,
                       const RunConfig& cfg, bool ok, std::vector<Framebuffer>& out);

// The host process's peak resident set (the report's host.peak_rss_bytes).
std::size_t peak_rss_bytes();

} // namespace zc
