#include "sim/platform_routes.hpp"

#include <functional>
#include <map>
#include <regex>
#include <set>
#include <vector>

#include "util/error.hpp"

namespace zc {

namespace {

// A zone of the file (or a cluster, a zone of its own), its hosts and its child zones: the points
// its routes join.
struct Zone {
  std::string id, routing;
  int parent = -1;
  std::vector<std::string> points; // its hosts and child zones, by id
  std::set<std::string> hosts;     // every host inside it, at any depth
};

struct Route {
  int zone;
  std::string src, dst, gw_src, gw_dst;
  bool symmetrical;
};

std::map<std::string, std::string> attributes(const std::string& text) {
  static const std::regex attr(R"re(([\w:-]+)\s*=\s*(?:"([^"]*)"|'([^']*)'))re");
  std::map<std::string, std::string> a;
  for (std::sregex_iterator m(text.begin(), text.end(), attr), end; m != end; ++m)
    a[(*m)[1]] = (*m)[2].matched ? (*m)[2].str() : (*m)[3].str();
  return a;
}

// The hosts of a cluster: prefix + each number of its radical + suffix.
std::vector<std::string> cluster_hosts(std::map<std::string, std::string> a) {
  std::vector<std::string> h;
  static const std::regex part(R"((\d{1,4})(?:-(\d{1,4}))?)");
  const std::string& r = a["radical"];
  for (std::sregex_iterator m(r.begin(), r.end(), part), end; m != end; ++m) {
    const int lo = std::stoi((*m)[1]), hi = (*m)[2].matched ? std::stoi((*m)[2]) : lo;
    for (int i = lo; i <= hi && h.size() < 4096; ++i)
      h.push_back(a["prefix"] + std::to_string(i) + a["suffix"]);
  }
  return h;
}

struct Layout {
  std::vector<Zone> zones;
  std::vector<Route> routes;
};

Layout read_layout(std::string xml) {
  xml = std::regex_replace(xml, std::regex(R"(<!--[\s\S]*?-->)"), "");
  static const std::regex tag(
      R"(<\s*(/?)\s*(zone|AS|host|route|zoneRoute|ASroute|bypassRoute|bypassZoneRoute|cluster)\b([^>]*?)(/?)>)");
  Layout l;
  std::vector<int> open;
  for (std::sregex_iterator t(xml.begin(), xml.end(), tag), end; t != end; ++t) {
    const bool closing = (*t)[1].length() > 0, self_closing = (*t)[4].length() > 0;
    const std::string name = (*t)[2];
    if (closing) {
      if ((name == "zone" || name == "AS") && !open.empty()) open.pop_back();
      continue;
    }
    auto a = attributes((*t)[3]);
    const int here = open.empty() ? -1 : open.back();
    if (name == "zone" || name == "AS" || name == "cluster") {
      Zone z;
      z.id = a["id"];
      z.routing = name == "cluster" ? "Cluster" : a["routing"];
      z.parent = here;
      if (here >= 0) l.zones[here].points.push_back(z.id);
      if (name == "cluster")
        for (const auto& h : cluster_hosts(a))
          z.points.push_back(h), z.hosts.insert(h);
      l.zones.push_back(z);
      if (name != "cluster" && !self_closing) open.push_back(int(l.zones.size()) - 1);
    } else if (name == "host" && here >= 0) {
      l.zones[here].points.push_back(a["id"]);
      l.zones[here].hosts.insert(a["id"]);
    } else if (name != "bypassRoute" && name != "bypassZoneRoute" && here >= 0) {
      const std::string sym = a.count("symmetrical") ? a["symmetrical"] : "YES";
      l.routes.push_back(
          {here, a["src"], a["dst"], a["gw_src"], a["gw_dst"], sym == "YES" || sym == "yes"});
    }
  }
  // Every host inside a zone, at any depth.
  for (int z = int(l.zones.size()) - 1; z >= 0; --z)
    if (l.zones[z].parent >= 0)
      l.zones[l.zones[z].parent].hosts.insert(l.zones[z].hosts.begin(), l.zones[z].hosts.end());
  return l;
}

const Zone* zone_named(const Layout& l, const std::string& id) {
  for (const auto& z : l.zones)
    if (z.id == id) return &z;
  return nullptr;
}

// A zone route's gateways are hosts of the zones it joins (SimGrid asserts it on first use).
void check_gateways(const Layout& l, const Route& r, const std::string& label) {
  const Zone* src = zone_named(l, r.src);
  const Zone* dst = zone_named(l, r.dst);
  if (!src || !dst) return; // a route between hosts
  auto bad = [&](const std::string& gw, const Zone& z, const char* which) {
    throw InputError(label, 0,
                     "zoneRoute " + r.src + " -> " + r.dst + ": " + which + "=\"" + gw +
                         "\" is not a host of zone '" + z.id + "'");
  };
  if (!src->hosts.count(r.gw_src)) bad(r.gw_src, *src, "gw_src");
  if (!dst->hosts.count(r.gw_dst)) bad(r.gw_dst, *dst, "gw_dst");
}

// Points of `z` reachable from `from` along the zone's routes (or against them).
std::set<std::string> reach(const std::map<std::string, std::set<std::string>>& next,
                            const std::string& from) {
  std::set<std::string> seen = {from};
  std::vector<std::string> todo = {from};
  while (!todo.empty()) {
    const std::string p = todo.back();
    todo.pop_back();
    auto it = next.find(p);
    if (it == next.end()) continue;
    for (const auto& q : it->second)
      if (seen.insert(q).second) todo.push_back(q);
  }
  return seen;
}

void check_zone(const Layout& l, int zi, const std::string& label) {
  const Zone& z = l.zones[zi];
  static const std::set<std::string> explicit_routes = {"Full", "Floyd", "Dijkstra",
                                                        "DijkstraCache"};
  if (!explicit_routes.count(z.routing) || z.points.size() < 2) return;
  std::map<std::string, std::set<std::string>> next, prev;
  for (const auto& r : l.routes) {
    if (r.zone != zi || r.src == r.dst) continue;
    check_gateways(l, r, label);
    next[r.src].insert(r.dst), prev[r.dst].insert(r.src);
    if (r.symmetrical) next[r.dst].insert(r.src), prev[r.src].insert(r.dst);
  }
  auto missing = [&](const std::string& a, const std::string& b) {
    throw InputError(label, 0,
                     "no route from '" + a + "' to '" + b + "' in zone '" + z.id + "' (routing " +
                         z.routing + ")");
  };
  if (z.routing == "Full") { // a route of its own for every ordered pair
    for (const auto& a : z.points)
      for (const auto& b : z.points)
        if (a != b && !next[a].count(b)) missing(a, b);
    return;
  }
  // Floyd and Dijkstra find paths: the routes must connect every point to every other.
  const std::string& first = z.points.front();
  const auto out = reach(next, first), in = reach(prev, first);
  for (const auto& p : z.points) {
    if (!out.count(p)) missing(first, p);
    if (!in.count(p)) missing(p, first);
  }
}

} // namespace

void check_declared_routes(const std::string& xml, const std::string& label) {
  const Layout l = read_layout(xml);
  for (int z = 0; z < int(l.zones.size()); ++z)
    check_zone(l, z, label);
}

} // namespace zc
