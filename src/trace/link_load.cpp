#include "trace/link_load.hpp"

#include <algorithm>

#include "machine/platform_xml.hpp"
#include "machine/topology.hpp"

namespace zc {

namespace {

std::vector<Link> message_route(Topology t, int P, int src, int dst) {
  std::vector<Link> r;
  if (src == P) r.push_back({P, 0});
  const int a = src == P ? 0 : src, b = dst == P ? 0 : dst;
  for (const auto& c : route(t, P, a, b))
    r.push_back(c);
  if (dst == P) r.push_back({0, P});
  return r;
}

} // namespace

std::string link_name(const Link& l, int P) {
  // The host computer's link by its platform names (machine/platform_xml.hpp).
  const std::string host = kHostComputerName;
  if (l.first == P) return std::string(kHostDownLink) + " (" + host + "->node 0)";
  if (l.second == P) return std::string(kHostUpLink) + " (node 0->" + host + ")";
  return "link " + std::to_string(l.first) + "->" + std::to_string(l.second);
}

std::map<Link, std::vector<std::pair<double, int>>> link_load(const Timeline& tl,
                                                              const std::string& topology) {
  const Topology topo = parse_topology(topology);
  std::map<Link, std::vector<std::pair<double, int>>> changes; // (time, +1/-1)
  for (const auto& m : tl.messages) {
    if (m["arrival_s"].is_null()) continue;
    const double t0 = m["send_start_s"], t1 = m["arrival_s"];
    for (const auto& l : message_route(topo, tl.nodes, m["src"], m["dst"])) {
      changes[l].push_back({t0, +1});
      changes[l].push_back({t1, -1});
    }
  }
  std::map<Link, std::vector<std::pair<double, int>>> out;
  for (auto& [l, ch] : changes) {
    std::sort(ch.begin(), ch.end()); // at equal times, departures (-1) first
    auto& steps = out[l];
    int n = 0;
    for (const auto& [t, d] : ch) {
      n += d;
      if (!steps.empty() && steps.back().first == t)
        steps.back().second = n;
      else
        steps.push_back({t, n});
    }
  }
  return out;
}

} // namespace zc
