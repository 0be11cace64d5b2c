// The report as JSON (docs/user-guide.md, "One run"): the one place its keys are spelt.
#include <sys/resource.h>

#include <algorithm>

#include "run/report.hpp"
#include "util/load_imbalance.hpp"

namespace zc {

std::vector<std::string> phase_names(const std::vector<NodeRecord>& records) {
  std::vector<std::string> order;
  for (const auto& c : records)
    for (const auto& n : c.phase_order)
      if (std::find(order.begin(), order.end(), n) == order.end()) order.push_back(n);
  return order;
}

std::optional<double> timed_region_s(const Report& r) {
  double timed_s = -1;
  for (int n = 0; n < r.nodes(); ++n) {
    const NodeStats& s = r.records[std::size_t(n)].stats;
    if (s.timed) timed_s = std::max(timed_s, s.timed_until_s() - s.timed_start_s);
  }
  return timed_s >= 0 ? std::optional<double>(timed_s) : std::nullopt;
}

namespace {

void add_header(nlohmann::json& j, const RunHeader& h) {
  j["machine"] = h.machine;
  j["platform"] = h.platform;
  j["nodes"] = h.nodes;
  j["topology"] = h.topology;
  j["fidelity"] = h.fidelity;
  j["algorithm"] = h.algorithm;
  j["options"] = h.options;
  j["frames"] = h.frames;
  j["scene"] = {{"path", h.scene.path},
                {"triangles", h.scene.triangles},
                {"vertices", h.scene.vertices},
                {"width", h.scene.width},
                {"height", h.scene.height}};
}

// Phases: max/mean/min over the nodes that entered the phase, what they sent in it, its band.
nlohmann::json phase_section(const Report& r) {
  nlohmann::json phases = nlohmann::json::array();
  for (const auto& n : phase_names(r.records)) {
    double mx = 0, sum = 0, mn = 1e300;
    int cnt = 0;
    Traffic sent; // over every node
    for (const auto& c : r.records) {
      auto it = c.phase_totals.find(n);
      if (it == c.phase_totals.end()) continue;
      mx = std::max(mx, it->second);
      mn = std::min(mn, it->second);
      sum += it->second;
      ++cnt;
      if (auto t = c.stats.phase_traffic.find(n); t != c.stats.phase_traffic.end())
        sent += t->second;
    }
    nlohmann::json p = {{"name", n},
                        {"max_s", mx},
                        {"mean_s", sum / cnt},
                        {"min_s", mn},
                        {"messages", sent.messages},
                        {"charged_bytes", sent.charged_bytes},
                        {"payload_bytes", sent.payload_bytes}};
    if (const auto b = r.phase_bands.find(n); b != r.phase_bands.end()) p["bands"] = b->second;
    phases.push_back(std::move(p));
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
  nlohmann::json e = {{"rank", rank_json(rec.who)},
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
void add_totals(nlohmann::json& j, const Report& r) {
  Counters total;
  std::uint64_t msgs = 0, bytes = 0, payload = 0;
  for (const NodeRecord& rec : r.records) {
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
  for (int n = 0; n < r.nodes(); ++n) {
    const NodeStats& s = r.records[std::size_t(n)].stats;
    max_sent = std::max(max_sent, s.bytes_sent);
    busy.push_back(s.busy_s);
  }
  if (const auto t = timed_region_s(r)) j["timed_s"] = *t;
  // bytes: what the modelled machine's network was charged; payload_bytes: zcube's payloads.
  j["communication"] = {{"messages", msgs},
                        {"bytes", bytes},
                        {"payload_bytes", payload},
                        {"concurrent_volume_bytes", max_sent}};
  j["counters"] = total;
  j["load_imbalance"] = load_imbalance(busy);
}

// "phases", "per_node", the totals, "timeline" (when the nodes kept logs), then the algorithm's
// metrics (its reporting node's) at the top level, objects merged key by key.
void add_node_sections(nlohmann::json& j, const Report& r) {
  j["phases"] = phase_section(r);
  j["per_node"] = nlohmann::json::array();
  for (const NodeRecord& rec : r.records)
    j["per_node"].push_back(node_entry(rec, r.virtual_time_s));
  add_totals(j, r);
  std::vector<const EventLog*> logs;
  std::vector<nlohmann::json> ranks;
  for (const NodeRecord& rec : r.records) {
    logs.push_back(rec.stats.log.get());
    ranks.push_back(rank_json(rec.who));
  }
  if (std::any_of(logs.begin(), logs.end(), [](const EventLog* l) { return l != nullptr; }))
    j["timeline"] = timeline_section(logs, ranks);
  if (r.records.empty()) return;
  for (auto& [k, v] : r.records.at(std::size_t(r.metrics_rank)).metrics.items()) {
    if (v.is_object() && j.contains(k) && j[k].is_object())
      j[k].update(v);
    else
      j[k] = v;
  }
}

// "model": the network figures the run used, the node memory, the host link and every counted
// operation's CPU cost on node 0 (docs/machines.md gives each one's source and range); "what_if":
// the what-if flags in force (empty when none), so that a report speaks for itself.
void add_model_section(nlohmann::json& j, const ModelSection& m) {
  const NetworkParams& n = m.net;
  j["model"] = {{"startup_short_s", n.startup_short_s},
                {"startup_long_s", n.startup_long_s},
                {"short_max_bytes", n.short_max_bytes},
                {"per_byte_s", n.per_byte_s},
                {"per_hop_s", n.per_hop_s},
                {"switching", n.switching == Switching::Circuit ? "circuit" : "store-and-forward"},
                {"node_memory_bytes", m.node_memory_bytes},
                {"os_resident_bytes", m.os_resident_bytes},
                {"host_startup_s", n.host_startup_s},
                {"host_per_byte_s", n.host_per_byte_s}};
  if (n.both_ways_Bps > 0) j["model"]["both_ways_Bps"] = n.both_ways_Bps;
  CostTable cpu_table = m.node0_cpu;
  nlohmann::json cpu = nlohmann::json::object();
  for (const auto& [name, v] : cpu_table.fields())
    cpu[name.starts_with("cost_") ? name.substr(5) : name] = *v;
  j["model"]["cpu_seconds"] = cpu;
  nlohmann::json w = nlohmann::json::object();
  for (const auto& [key, value] : what_if_columns(m.what_ifs))
    w[key] = value;
  j["what_if"] = w;
}

void add_host_section(nlohmann::json& j, const HostUse& h) {
  j["host"] = {{"wall_time_s", h.wall_time_s}, {"peak_rss_bytes", h.peak_rss_bytes}};
  if (h.page_faults_timed) j["host"]["page_faults_timed"] = *h.page_faults_timed;
  if (h.core_share) j["host"]["core_share"] = *h.core_share;
}

} // namespace

nlohmann::json report_json(const Report& r) {
  nlohmann::json j;
  if (r.measured) {
    j["backend"] = "mpi";
    j["measured"] = true;
    j["clock"] = r.measured->clock;
    j["processors"] = r.measured->processors;
  }
  add_header(j, r.header);
  j["status"] = r.status;
  if (!r.error.empty()) j["error"] = r.error;
  j["virtual_time_s"] = r.virtual_time_s;
  add_node_sections(j, r);
  if (r.model) add_model_section(j, *r.model);
  if (r.simulation_cost) j["simulation_cost"] = *r.simulation_cost;
  j["image"] = r.image;
  add_host_section(j, r.host);
  if (!r.bands.is_null()) j["bands"] = r.bands;
  if (!r.sensitivity.is_null()) j["sensitivity"] = r.sensitivity;
  return j;
}

std::size_t peak_rss_bytes() {
  struct rusage ru {};
  getrusage(RUSAGE_SELF, &ru);
  return std::size_t(ru.ru_maxrss) * 1024;
}

} // namespace zc
