#include "run/event_log.hpp"

#include <map>
#include <tuple>

namespace zc {

const char* activity_name(Activity a) {
  switch (a) {
  case Activity::Compute:
    return "compute";
  case Activity::Send:
    return "send";
  default:
    return "wait";
  }
}

void EventLog::activity(Activity kind, double begin_s, double end_s) {
  if (!(end_s > begin_s)) return;
  if (!activities.empty() && activities.back().kind == kind && activities.back().end_s == begin_s)
    activities.back().end_s = end_s;
  else
    activities.push_back({kind, begin_s, end_s});
}

// Compact on the wire (the MPI backend gathers logs as JSON): one array per event.
void to_json(nlohmann::json& j, const EventLog& log) {
  j = nlohmann::json::object();
  auto& ph = j["phases"] = nlohmann::json::array();
  for (const auto& p : log.phases)
    ph.push_back({p.name, p.depth, p.begin_s, p.end_s});
  auto& ac = j["activities"] = nlohmann::json::array();
  for (const auto& a : log.activities)
    ac.push_back({int(a.kind), a.begin_s, a.end_s});
  auto& se = j["sends"] = nlohmann::json::array();
  for (const auto& s : log.sends)
    se.push_back({s.dst, s.tag, s.bytes, s.hops, s.start_s});
  auto& re = j["recvs"] = nlohmann::json::array();
  for (const auto& r : log.recvs)
    re.push_back({r.src, r.tag, r.arrival_s, r.done_s});
}

void from_json(const nlohmann::json& j, EventLog& log) {
  log = EventLog{};
  for (const auto& p : j.at("phases"))
    log.phases.push_back({p[0], p[1], p[2], p[3]});
  for (const auto& a : j.at("activities"))
    log.activities.push_back({Activity(a[0].get<int>()), a[1], a[2]});
  for (const auto& s : j.at("sends"))
    log.sends.push_back({s[0], s[1], s[2], s[3], s[4]});
  for (const auto& r : j.at("recvs"))
    log.recvs.push_back({r[0], r[1], r[2], r[3]});
}

int message_hops(Topology t, int nodes, int src, int dst) {
  if (src == dst) return 0;
  if (src == nodes) return 1 + hops(t, nodes, 0, dst);
  if (dst == nodes) return hops(t, nodes, src, 0) + 1;
  return hops(t, nodes, src, dst);
}

nlohmann::json timeline_section(const std::vector<const EventLog*>& logs,
                                const std::vector<nlohmann::json>& ranks) {
  nlohmann::json nodes = nlohmann::json::array();
  for (std::size_t i = 0; i < logs.size(); ++i) {
    nlohmann::json phases = nlohmann::json::array(), acts = nlohmann::json::array();
    if (logs[i]) {
      for (const auto& p : logs[i]->phases)
        phases.push_back(
            {{"name", p.name}, {"depth", p.depth}, {"begin_s", p.begin_s}, {"end_s", p.end_s}});
      for (const auto& a : logs[i]->activities)
        acts.push_back({activity_name(a.kind), a.begin_s, a.end_s});
    }
    nodes.push_back({{"rank", ranks[i]}, {"phases", phases}, {"activities", acts}});
  }
  // Receives per (src, dst, tag) in order, to pair with the sends.
  std::map<std::tuple<int, int, int>, std::vector<const RecvEvent*>> recvd;
  for (std::size_t d = 0; d < logs.size(); ++d)
    if (logs[d])
      for (const auto& r : logs[d]->recvs)
        recvd[{r.src, int(d), r.tag}].push_back(&r);
  std::map<std::tuple<int, int, int>, std::size_t> used;
  nlohmann::json msgs = nlohmann::json::array();
  for (std::size_t s = 0; s < logs.size(); ++s) {
    if (!logs[s]) continue;
    for (const auto& e : logs[s]->sends) {
      const std::tuple<int, int, int> key{int(s), e.dst, e.tag};
      const auto& rs = recvd[key];
      const std::size_t k = used[key]++;
      const RecvEvent* r = k < rs.size() ? rs[k] : nullptr;
      msgs.push_back({{"src", s},
                      {"dst", e.dst},
                      {"tag", e.tag},
                      {"bytes", e.bytes},
                      {"hops", e.hops},
                      {"send_start_s", e.start_s},
                      {"arrival_s", r ? nlohmann::json(r->arrival_s) : nlohmann::json()},
                      {"recv_done_s", r ? nlohmann::json(r->done_s) : nlohmann::json()}});
    }
  }
  return {{"nodes", nodes}, {"messages", msgs}};
}

} // namespace zc
