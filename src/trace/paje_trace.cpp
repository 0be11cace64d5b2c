#include "trace/paje_trace.hpp"

#include <algorithm>
#include <cstdio>
#include <tuple>

#include "trace/link_load.hpp"

namespace zc {

namespace {

// The event definitions this file uses (the Paje file format, PajeNG's documentation).
constexpr const char* kHeader = R"(%EventDef PajeDefineContainerType 0
% Alias string
% Type string
% Name string
%EndEventDef
%EventDef PajeDefineVariableType 1
% Alias string
% Type string
% Name string
% Color color
%EndEventDef
%EventDef PajeDefineStateType 2
% Alias string
% Type string
% Name string
%EndEventDef
%EventDef PajeDefineEntityValue 3
% Alias string
% Type string
% Name string
% Color color
%EndEventDef
%EventDef PajeDefineLinkType 4
% Alias string
% Type string
% StartContainerType string
% EndContainerType string
% Name string
%EndEventDef
%EventDef PajeCreateContainer 5
% Time date
% Alias string
% Type string
% Container string
% Name string
%EndEventDef
%EventDef PajeDestroyContainer 6
% Time date
% Type string
% Name string
%EndEventDef
%EventDef PajeSetVariable 7
% Time date
% Type string
% Container string
% Value double
%EndEventDef
%EventDef PajeSetState 8
% Time date
% Type string
% Container string
% Value string
%EndEventDef
%EventDef PajePushState 9
% Time date
% Type string
% Container string
% Value string
%EndEventDef
%EventDef PajePopState 10
% Time date
% Type string
% Container string
%EndEventDef
%EventDef PajeStartLink 11
% Time date
% Type string
% Container string
% Value string
% StartContainer string
% Key string
% Size double
%EndEventDef
%EventDef PajeEndLink 12
% Time date
% Type string
% Container string
% Value string
% EndContainer string
% Key string
%EndEventDef
0 MACHINE 0 "Machine"
0 NODE MACHINE "Node"
0 LINK MACHINE "Link"
2 PHASE NODE "Phase"
2 ACTIVITY NODE "Activity"
3 compute ACTIVITY "compute" "0.20 0.63 0.17"
3 send ACTIVITY "send" "0.89 0.10 0.11"
3 wait ACTIVITY "wait" "1.00 0.50 0.00"
3 idle ACTIVITY "idle" "0.85 0.85 0.85"
1 INFLIGHT LINK "Messages in flight" "0.12 0.47 0.71"
4 MESSAGE MACHINE NODE NODE "Message"
)";

// One line of the body, ordered by time; at equal times by `order` (what ends before what begins,
// the outer phase pushed first and popped last), then as emitted.
struct Line {
  double t;
  int order;
  std::size_t seq;
  std::string text;
};

std::string exact_num(double v) { // round-trips
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s)
    q += c == '"' ? '\'' : c == ',' ? ';' : c; // pj_dump writes CSV
  return q + "\"";
}

std::string node_alias(int i) {
  return std::string("n") += std::to_string(i);
}

// One event line: its fields separated by spaces.
std::string fields(std::initializer_list<std::string> f) {
  std::string line;
  for (const auto& x : f) {
    if (!line.empty()) line += ' ';
    line += x;
  }
  return line;
}

} // namespace

void write_paje_trace(const Timeline& tl, const std::string& topology, std::ostream& out) {
  std::vector<Line> lines;
  auto add = [&](double t, int order, const std::string& text) {
    lines.push_back({t, order, lines.size(), text});
  };
  add(0, -1000, fields({"5", "0", "m", "MACHINE", "0", quoted(tl.title)}));
  for (const auto& n : tl.tracks) {
    const std::string c = node_alias(n.index);
    add(0, -999, fields({"5", "0", c, "NODE", "m", quoted(n.label)}));
    for (const auto& p : n.phases) {
      if (!(p.end_s > p.begin_s)) continue; // an instant has no state to show
      add(p.begin_s, 100 + p.depth,
          fields({"9", exact_num(p.begin_s), "PHASE", c, quoted(p.name)}));
      add(p.end_s, 0 - p.depth, fields({"10", exact_num(p.end_s), "PHASE", c}));
    }
    for (const auto& a : n.activities)
      add(a.begin_s, 200, fields({"8", exact_num(a.begin_s), "ACTIVITY", c, a.name}));
  }
  std::size_t key = 0;
  for (const auto& m : tl.messages) {
    if (m["arrival_s"].is_null()) continue;
    const std::string k = std::string("k") += std::to_string(key++);
    const std::string tag = std::string("tag") += std::to_string(m["tag"].get<int>());
    const double t0 = m["send_start_s"], t1 = m["arrival_s"];
    add(t0, 300,
        fields({"11", exact_num(t0), "MESSAGE", "m", tag, node_alias(m["src"]), k,
                exact_num(m["bytes"].get<double>())}));
    add(t1, 301, fields({"12", exact_num(t1), "MESSAGE", "m", tag, node_alias(m["dst"]), k}));
  }
  for (const auto& [l, steps] : link_load(tl, topology)) {
    std::string c = "l";
    ((c += std::to_string(l.first)) += '_') += std::to_string(l.second);
    add(0, -998, fields({"5", "0", c, "LINK", "m", quoted(link_name(l, tl.nodes))}));
    add(0, -997, fields({"7", "0", "INFLIGHT", c, "0"}));
    for (const auto& [t, n] : steps)
      add(t, 250, fields({"7", exact_num(t), "INFLIGHT", c, std::to_string(n)}));
  }
  std::sort(lines.begin(), lines.end(), [](const Line& a, const Line& b) {
    return std::tie(a.t, a.order, a.seq) < std::tie(b.t, b.order, b.seq);
  });
  out << kHeader;
  for (const auto& l : lines)
    out << l.text << "\n";
  out << "6 " << exact_num(tl.total_s) << " MACHINE m\n";
}

} // namespace zc
