#include "trace/timeline.hpp"

#include <algorithm>
#include <filesystem>

#include "util/error.hpp"

namespace zc {

namespace {

// Every instant of [0, total] as one activity: the idle gaps between the activities filled in, and
// every slice (idle or not) cut where a phase begins or ends, so that each nests inside the phases
// (a trace viewer needs proper nesting on a track: Perfetto drops a slice that crosses another).
std::vector<Span> with_idle(const std::vector<Span>& acts, const std::vector<Span>& phases,
                            double total) {
  std::vector<double> cuts;
  for (const auto& p : phases) {
    cuts.push_back(p.begin_s);
    cuts.push_back(p.end_s);
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<Span> out;
  auto add = [&](const std::string& name, double a, double b) {
    auto it = std::upper_bound(cuts.begin(), cuts.end(), a);
    for (; it != cuts.end() && *it < b; ++it) {
      out.push_back({name, 0, a, *it});
      a = *it;
    }
    if (b > a) out.push_back({name, 0, a, b});
  };
  double t = 0;
  for (const auto& a : acts) {
    if (a.begin_s > t) add("idle", t, a.begin_s);
    if (a.end_s > a.begin_s)
      add(a.name, a.begin_s, a.end_s);
    else
      out.push_back(a);
    t = std::max(t, a.end_s);
  }
  if (total > t) add("idle", t, total);
  return out;
}

} // namespace

Timeline read_timeline(const nlohmann::json& r, const std::string& where) {
  if (!r.contains("timeline"))
    throw InputError(where, 0, "the report has no timeline (run with --trace or --gantt)");
  Timeline tl;
  tl.nodes = r.at("nodes");
  tl.total_s = r.at("virtual_time_s");
  const std::string scene = std::filesystem::path(r["scene"].value("path", "")).stem().string();
  tl.title = r.value("machine", "?") + ", " + r.value("algorithm", "?") + ", " + scene +
             ", P = " + std::to_string(tl.nodes);
  const auto& t = r.at("timeline");
  for (std::size_t i = 0; i < t.at("nodes").size(); ++i) {
    const auto& n = t["nodes"][i];
    NodeTimeline nt;
    nt.index = int(i);
    nt.label = n["rank"].is_string() ? "host (" + n["rank"].get<std::string>() + ")"
                                     : "node " + std::to_string(n["rank"].get<int>());
    for (const auto& p : n.at("phases"))
      nt.phases.push_back({p["name"], p["depth"], p["begin_s"], p["end_s"]});
    std::vector<Span> acts;
    for (const auto& a : n.at("activities"))
      acts.push_back({a[0], 0, a[1], a[2]});
    // Phases outermost first, then by start: the order nested slices are drawn in.
    std::stable_sort(nt.phases.begin(), nt.phases.end(), [](const Span& a, const Span& b) {
      return a.begin_s != b.begin_s ? a.begin_s < b.begin_s : a.depth < b.depth;
    });
    nt.activities = with_idle(acts, nt.phases, tl.total_s);
    tl.tracks.push_back(std::move(nt));
  }
  tl.messages = t.at("messages");
  return tl;
}

} // namespace zc
