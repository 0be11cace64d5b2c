#include "run/report.hpp"

#include <sys/resource.h>

#include <algorithm>

#include "algo/algorithm.hpp"
#include "geometry/camera_path.hpp"
#include "raster/image_io.hpp"
#include "raster/renderer.hpp"
#include "util/load_imbalance.hpp"

namespace zc {

void to_json(nlohmann::json& j, const Traffic& t) {
  j = {{"charged_bytes", t.charged_bytes},
       {"payload_bytes", t.payload_bytes},
       {"messages", t.messages}};
}

void from_json(const nlohmann::json& j, Traffic& t) {
  t.charged_bytes = j.at("charged_bytes");
  t.payload_bytes = j.at("payload_bytes");
  t.messages = j.at("messages");
}

void to_json(nlohmann::json& j, const NodeRecord& r) {
  nlohmann::json work = nlohmann::json::object();
  for (const auto& [n, w] : r.phase_work)
    work[n] = w;
  j = {{"rank", r.rank},
       {"busy_s", r.stats.busy_s},
       {"comm_s", r.stats.comm_s},
       {"finish_s", r.stats.finish_s},
       {"bytes_sent", r.stats.bytes_sent},
       {"payload_bytes_sent", r.stats.payload_bytes_sent},
       {"messages", r.stats.messages},
       {"phase_traffic", r.stats.phase_traffic},
       {"peak_memory", r.stats.peak_memory},
       {"timed", r.stats.timed},
       {"timed_start_s", r.stats.timed_start_s},
       {"timed_ended", r.stats.timed_ended},
       {"timed_end_s", r.stats.timed_end_s},
       {"phase_order", r.phase_order},
       {"phase_totals", r.phase_totals},
       {"phase_work", work},
       {"work", r.work},
       {"metrics", r.metrics}};
  if (r.stats.log) j["timeline"] = *r.stats.log;
}

void from_json(const nlohmann::json& j, NodeRecord& r) {
  r.rank = j.at("rank");
  r.stats.busy_s = j.at("busy_s");
  r.stats.comm_s = j.at("comm_s");
  r.stats.finish_s = j.at("finish_s");
  r.stats.bytes_sent = j.at("bytes_sent");
  r.stats.payload_bytes_sent = j.at("payload_bytes_sent");
  r.stats.messages = j.at("messages");
  r.stats.phase_traffic = j.at("phase_traffic").get<std::map<std::string, Traffic>>();
  r.stats.peak_memory = j.at("peak_memory");
  r.stats.timed = j.value("timed", false);
  r.stats.timed_start_s = j.value("timed_start_s", 0.0);
  r.stats.timed_ended = j.value("timed_ended", false);
  r.stats.timed_end_s = j.value("timed_end_s", 0.0);
  r.phase_order = j.at("phase_order").get<std::vector<std::string>>();
  r.phase_totals = j.at("phase_totals").get<std::map<std::string, double>>();
  r.phase_work.clear();
  for (const auto& [n, w] : j.at("phase_work").items())
    r.phase_work[n] = w.get<Counters>();
  r.work = j.at("work").get<Counters>();
  r.metrics = j.at("metrics");
  r.stats.log = j.contains("timeline")
                    ? std::make_shared<EventLog>(j.at("timeline").get<EventLog>())
                    : nullptr;
}

void add_run_header(nlohmann::json& j, const RunHeader& h, const RunConfig& cfg,
                    const std::string& algorithm, const Scene& scene) {
  j["machine"] = h.machine;
  j["platform"] = h.platform;
  j["nodes"] = h.nodes;
  j["topology"] = h.topology;
  j["fidelity"] = h.fidelity;
  j["algorithm"] = algorithm;
  // Every option of the algorithm, the defaults included: a report says which variant ran.
  nlohmann::json options = cfg.options.values;
  for (const auto& a : algorithms()) // a test's own algorithm is not registered: none
    if (a.name == algorithm)
      for (const auto& o : a.options)
        if (!options.contains(o.name)) options[o.name] = o.default_value;
  j["options"] = options;
  j["frames"] = cfg.options.frames;
  j["scene"] = {{"path", h.scene_path},
                {"triangles", scene.triangles.size()},
                {"vertices", scene.vertices.size()},
                {"width", scene.width},
                {"height", scene.height}};
}

namespace {

// Phases: per node totals, then max/mean/min over the nodes that entered the phase.
nlohmann::json phase_section(const std::vector<NodeRecord>& nodes) {
  std::vector<std::string> order;
  for (const auto& c : nodes)
    for (const auto& n : c.phase_order)
      if (std::find(order.begin(), order.end(), n) == order.end()) order.push_back(n);
  nlohmann::json phases = nlohmann::json::array();
  for (const auto& n : order) {
    double mx = 0, sum = 0, mn = 1e300;
    int cnt = 0;
    Traffic sent; // over every node
    for (const auto& c : nodes) {
      auto it = c.phase_totals.find(n);
      if (it == c.phase_totals.end()) continue;
      mx = std::max(mx, it->second);
      mn = std::min(mn, it->second);
      sum += it->second;
      ++cnt;
      if (auto t = c.stats.phase_traffic.find(n); t != c.stats.phase_traffic.end())
        sent += t->second;
    }
    phases.push_back({{"name", n},
                      {"max_s", mx},
                      {"mean_s", sum / cnt},
                      {"min_s", mn},
                      {"messages", sent.messages},
                      {"charged_bytes", sent.charged_bytes},
                      {"payload_bytes", sent.payload_bytes}});
  }
  return phases;
}

// One node's entry of "per_node".
nlohmann::json node_entry(const NodeRecord& rec, double total_s) {
  const NodeStats& s = rec.stats;
  nlohmann::json ph = nlohmann::json::object();
  for (const auto& [n, t] : rec.phase_totals)
    ph[n] = t;
  // Operations per phase, zero counts left out (the calibration's linear model).
  nlohmann::json pw = nlohmann::json::object();
  for (const auto& [n, w] : rec.phase_work)
    if (nlohmann::json nz = nonzero_json(w); !nz.empty())
      pw[n.empty() ? "(no phase)" : n] = std::move(nz);
  nlohmann::json e = {{"rank", rec.rank},
                      {"busy_s", s.busy_s},
                      {"comm_s", s.comm_s},
                      {"idle_s", std::max(0.0, total_s - s.busy_s - s.comm_s)},
                      {"bytes_sent", s.bytes_sent},
                      {"payload_bytes_sent", s.payload_bytes_sent},
                      {"messages", s.messages},
                      {"peak_memory_bytes", s.peak_memory},
                      {"phases", ph},
                      {"phase_work", pw}};
  if (!rec.metrics.empty()) e["metrics"] = rec.metrics;
  return e;
}

// The run's totals: communication, counters, load imbalance and the paper's timed region.
void add_totals(nlohmann::json& j, const std::vector<NodeRecord>& nodes, int P) {
  Counters total;
  std::uint64_t msgs = 0, bytes = 0, payload = 0;
  for (const NodeRecord& rec : nodes) {
    total += rec.work;
    msgs += rec.stats.messages;
    bytes += rec.stats.bytes_sent;
    payload += rec.stats.payload_bytes_sent;
  }
  // Defaults of the report keys an algorithm may refine through its metrics (Kurc et al.
  // replace both by their own definitions: the sum over communication steps of the largest
  // volume of a step, and the imbalance of the merge loads).
  //  concurrent_volume_bytes: the largest volume one node sent (a lower bound of the time-critical
  //    volume when the algorithm does not report its steps);
  //  load_imbalance: (max - min) / mean of the nodes' busy (CPU) time, the definition the
  //    algorithms use for their own loads; 0 when nobody worked.
  std::uint64_t max_sent = 0;
  std::vector<double> busy;
  // The paper's timed region (docs/papers.md): the longest (end - start) over the nodes that
  // started one, the end being the node's finish unless it marked one; absent when no node
  // started one (the whole run is timed).
  double timed_s = -1;
  for (int r = 0; r < P; ++r) {
    const NodeStats& s = nodes[std::size_t(r)].stats;
    max_sent = std::max(max_sent, s.bytes_sent);
    busy.push_back(s.busy_s);
    if (s.timed) timed_s = std::max(timed_s, s.timed_until_s() - s.timed_start_s);
  }
  if (timed_s >= 0) j["timed_s"] = timed_s;
  // bytes: what the modelled machine's network was charged; payload_bytes: zcube's payloads.
  j["communication"] = {{"messages", msgs},
                        {"bytes", bytes},
                        {"payload_bytes", payload},
                        {"concurrent_volume_bytes", max_sent}};
  j["counters"] = total;
  j["load_imbalance"] = load_imbalance(busy);
}

} // namespace

void add_node_sections(nlohmann::json& j, const std::vector<NodeRecord>& nodes, int P,
                       double total_s) {
  j["phases"] = phase_section(nodes);
  j["per_node"] = nlohmann::json::array();
  for (const NodeRecord& rec : nodes)
    j["per_node"].push_back(node_entry(rec, total_s));
  add_totals(j, nodes, P);
  std::vector<const EventLog*> logs;
  std::vector<nlohmann::json> ranks;
  for (const NodeRecord& rec : nodes) {
    logs.push_back(rec.stats.log.get());
    ranks.push_back(rec.rank);
  }
  if (std::any_of(logs.begin(), logs.end(), [](const EventLog* l) { return l != nullptr; }))
    j["timeline"] = timeline_section(logs, ranks);
  // Algorithm metrics (node 0's) merge into the top level, objects key by key.
  for (auto& [k, v] : nodes.front().metrics.items()) {
    if (v.is_object() && j.contains(k) && j[k].is_object())
      j[k].update(v);
    else
      j[k] = v;
  }
}

namespace {
ReferenceLookup& reference_lookup() {
  static ReferenceLookup lookup;
  return lookup;
}
} // namespace

void set_reference_lookup(ReferenceLookup lookup) {
  reference_lookup() = std::move(lookup);
}

ReferenceFrame reference_frame(const Scene& scene, int frame, int frames) {
  Scene sf = scene;
  sf.camera = camera_at_frame(scene.camera, frame, frames);
  const Framebuffer seq = render_scene(sf, 1).image;
  return {image_sha256(seq), depth_map(seq)};
}

void add_image_section(nlohmann::json& j, std::vector<FrameImage>& images, const Scene& scene,
                       const RunConfig& cfg, bool ok, std::vector<Framebuffer>& out) {
  // Rows delivered straight to the output device: pasted into one picture per frame.
  {
    std::map<int, Framebuffer> composed;
    std::vector<FrameImage> whole;
    for (auto& fi : images) {
      if (!fi.partial) {
        whole.push_back(std::move(fi));
        continue;
      }
      auto it = composed.find(fi.frame);
      if (it == composed.end())
        it = composed
                 .emplace(fi.frame,
                          Framebuffer(scene.width, RowSet::all(scene.height), scene.background))
                 .first;
      it->second.paste(fi.image);
    }
    for (auto& [f, fb] : composed)
      whole.push_back({f, std::move(fb)});
    images = std::move(whole);
  }
  // Images, in frame order, against the host's sequential renderer.
  std::sort(images.begin(), images.end(),
            [](const FrameImage& a, const FrameImage& b) { return a.frame < b.frame; });
  nlohmann::json img = nlohmann::json::object();
  // An algorithm that draws no picture (a benchmark) has nothing to compare.
  const bool compare =
      cfg.compare_with_sequential &&
      (cfg.custom ? cfg.custom->draws_picture : find_algorithm(cfg.algorithm).draws_picture);
  if (ok) {
    // Colour and depth (the --image and --depth maps) against the sequential renderer's.
    bool same_colour = int(images.size()) == cfg.options.frames, same_depth = same_colour;
    std::vector<std::string> shas;
    for (int f = 0; f < int(images.size()); ++f) {
      shas.push_back(image_sha256(images[f].image));
      if (compare) {
        const auto& lookup = reference_lookup();
        const ReferenceFrame* drawn = lookup ? lookup(scene, f, cfg.options.frames) : nullptr;
        const ReferenceFrame seq =
            drawn ? ReferenceFrame{} : reference_frame(scene, f, cfg.options.frames);
        const ReferenceFrame& ref = drawn ? *drawn : seq;
        same_colour = same_colour && ref.sha256 == shas.back();
        same_depth = same_depth && same_depth_map(images[f].image, ref.depth);
      }
    }
    img["sha256"] = shas.empty() ? nlohmann::json(nullptr) : nlohmann::json(shas.back());
    if (shas.size() > 1) img["frames_sha256"] = shas;
    img["identical_to_sequential"] =
        compare ? nlohmann::json(same_colour && same_depth) : nlohmann::json(nullptr);
    if (compare) {
      img["compared_with_sequential"] = "colour and depth";
      if (!same_colour || !same_depth)
        img["differs_from_sequential"] = !same_colour && !same_depth ? "colour and depth"
                                         : !same_colour              ? "colour"
                                                                     : "depth";
    }
  }
  j["image"] = img;
  for (auto& fi : images)
    out.push_back(std::move(fi.image));
}

std::size_t peak_rss_bytes() {
  struct rusage ru {};
  getrusage(RUSAGE_SELF, &ru);
  return std::size_t(ru.ru_maxrss) * 1024;
}

} // namespace zc
