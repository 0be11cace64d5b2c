#include "trace/chrome_trace.hpp"

#include <cmath>
#include <cstdint>
#include <map>

#include "trace/link_load.hpp"

namespace zc {

namespace {

constexpr int kMachinePid = 1, kLinksPid = 2;

// Times in whole nanoseconds, written in microseconds: a viewer reads them back as the same
// nanoseconds (Perfetto rounds ts x 1000), so slices that share a boundary in the timeline share it
// exactly in the trace and nest properly.
std::int64_t ns(double s) {
  return std::llround(s * 1e9);
}

nlohmann::json slice(const Span& s, const char* cat, int tid) {
  return {{"name", s.name},
          {"cat", cat},
          {"ph", "X"},
          {"pid", kMachinePid},
          {"tid", tid},
          {"ts", double(ns(s.begin_s)) / 1e3},
          {"dur", double(ns(s.end_s) - ns(s.begin_s)) / 1e3}};
}

nlohmann::json meta(const char* what, int pid, int tid, const std::string& name) {
  return {{"name", what}, {"ph", "M"}, {"pid", pid}, {"tid", tid}, {"args", {{"name", name}}}};
}

void add_flows(const Timeline& tl, nlohmann::json& ev) {
  std::uint64_t id = 0;
  for (const auto& m : tl.messages) {
    if (m["arrival_s"].is_null()) continue; // never received
    const nlohmann::json args = {{"bytes", m["bytes"]},
                                 {"tag", m["tag"]},
                                 {"hops", m["hops"]},
                                 {"src", m["src"]},
                                 {"dst", m["dst"]},
                                 {"send_start_s", m["send_start_s"]},
                                 {"arrival_s", m["arrival_s"]},
                                 {"recv_done_s", m["recv_done_s"]}};
    const std::string name = "message " + std::to_string(m["bytes"].get<std::uint64_t>()) + " B";
    ev.push_back({{"name", name},
                  {"cat", "message"},
                  {"ph", "s"},
                  {"id", id},
                  {"pid", kMachinePid},
                  {"tid", m["src"]},
                  {"ts", double(ns(m["send_start_s"].get<double>())) / 1e3},
                  {"args", args}});
    ev.push_back({{"name", name},
                  {"cat", "message"},
                  {"ph", "f"},
                  {"bp", "e"},
                  {"id", id},
                  {"pid", kMachinePid},
                  {"tid", m["dst"]},
                  {"ts", double(ns(m["arrival_s"].get<double>())) / 1e3}});
    ++id;
  }
}

} // namespace

nlohmann::json chrome_trace(const Timeline& tl, const std::string& topology) {
  nlohmann::json ev = nlohmann::json::array();
  ev.push_back(meta("process_name", kMachinePid, 0, tl.title));
  for (const auto& n : tl.tracks) {
    ev.push_back(meta("thread_name", kMachinePid, n.index, n.label));
    ev.push_back({{"name", "thread_sort_index"},
                  {"ph", "M"},
                  {"pid", kMachinePid},
                  {"tid", n.index},
                  {"args", {{"sort_index", n.index}}}});
    for (const auto& p : n.phases)
      ev.push_back(slice(p, "phase", n.index));
    for (const auto& a : n.activities)
      ev.push_back(slice(a, "activity", n.index));
  }
  add_flows(tl, ev);
  // Links: one counter track per directed channel that carried a message.
  const auto load = link_load(tl, topology);
  if (!load.empty()) ev.push_back(meta("process_name", kLinksPid, 0, "links (messages in flight)"));
  for (const auto& [link, steps] : load)
    for (const auto& [t, n] : steps)
      ev.push_back({{"name", link_name(link, tl.nodes)},
                    {"ph", "C"},
                    {"pid", kLinksPid},
                    {"ts", double(ns(t)) / 1e3},
                    {"args", {{"messages", n}}}});
  return {{"traceEvents", ev},
          {"displayTimeUnit", "ns"},
          {"otherData", {{"title", tl.title}, {"virtual_time_s", tl.total_s}}}};
}

} // namespace zc
