#include "sim/platform_routes.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include <pugixml.hpp>

#include "sim/platform_values.hpp"
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
  bool between_zones; // a <zoneRoute>
  std::string src, dst, gw_src, gw_dst;
  bool symmetrical;
  std::vector<std::string> links;
  int line; // in the file
};

struct Layout {
  std::vector<Zone> zones;
  std::vector<Route> routes;
  std::set<std::string> links; // every <link> id
};

// The hosts of a cluster: prefix + each number of its radical + suffix.
std::vector<std::string> cluster_hosts(pugi::xml_node c) {
  std::vector<std::string> h;
  const std::string prefix = c.attribute("prefix").value(), suffix = c.attribute("suffix").value();
  for (auto [lo, hi] : radical_ranges(c.attribute("radical").value()))
    for (int i = lo; i <= hi && lo >= 0 && h.size() < 4096; ++i)
      h.push_back(prefix + std::to_string(i) + suffix);
  return h;
}

Route read_route(pugi::xml_node n, int zone, int line) {
  const std::string sym = n.attribute("symmetrical").as_string("YES");
  Route r{zone,
          std::string(n.name()) == "zoneRoute",
          n.attribute("src").value(),
          n.attribute("dst").value(),
          n.attribute("gw_src").value(),
          n.attribute("gw_dst").value(),
          sym == "YES" || sym == "yes",
          {},
          line};
  for (pugi::xml_node l : n.children("link_ctn"))
    r.links.push_back(l.attribute("id").value());
  return r;
}

// The line of an element: its offset in the text counted in newlines.
int line_at(const std::string& xml, pugi::xml_node n) {
  const std::ptrdiff_t at = std::min<std::ptrdiff_t>(n.offset_debug(), std::ptrdiff_t(xml.size()));
  return at < 0 ? 0 : 1 + int(std::count(xml.begin(), xml.begin() + at, '\n'));
}

void read_zone(const std::string& xml, pugi::xml_node n, int parent, Layout& l) {
  const std::string name = n.name();
  Zone z;
  z.id = n.attribute("id").value();
  z.routing = name == "cluster" ? "Cluster" : n.attribute("routing").value();
  z.parent = parent;
  if (parent >= 0) l.zones[parent].points.push_back(z.id);
  if (name == "cluster")
    for (const auto& h : cluster_hosts(n))
      z.points.push_back(h), z.hosts.insert(h);
  l.zones.push_back(z);
  if (name == "cluster") return;
  const int here = int(l.zones.size()) - 1;
  for (pugi::xml_node c : n.children()) {
    const std::string child = c.name();
    if (child == "zone" || child == "cluster") {
      read_zone(xml, c, here, l);
    } else if (child == "host") {
      l.zones[here].points.push_back(c.attribute("id").value());
      l.zones[here].hosts.insert(c.attribute("id").value());
    } else if (child == "link") {
      l.links.insert(c.attribute("id").value());
    } else if (child == "route" || child == "zoneRoute") {
      l.routes.push_back(read_route(c, here, line_at(xml, c)));
    }
  }
}

Layout read_layout(const std::string& xml, const std::string& label) {
  pugi::xml_document doc;
  const pugi::xml_parse_result r = doc.load_buffer(xml.data(), xml.size());
  if (!r) throw InputError(label, 0, std::string("not well-formed XML: ") + r.description());
  Layout l;
  for (pugi::xml_node z : doc.child("platform").children("zone"))
    read_zone(xml, z, -1, l);
  // Every host inside a zone, at any depth (a child zone comes after its parent).
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

std::string route_name(const Route& r) {
  return std::string(r.between_zones ? "zoneRoute " : "route ") + r.src + " -> " + r.dst;
}

// A route joins points of its own zone (hosts for a <route>, child zones for a <zoneRoute>) over
// links the file declares; a zone route's gateways are hosts of the zones it joins (SimGrid asserts
// it on first use).
void check_ends(const Layout& l, const Route& r, const std::string& label) {
  const Zone& z = l.zones[r.zone];
  for (const std::string* end : {&r.src, &r.dst}) {
    const Zone* child = zone_named(l, *end);
    const bool point = std::find(z.points.begin(), z.points.end(), *end) != z.points.end();
    if (!point || (child != nullptr) != r.between_zones)
      throw InputError(label, r.line,
                       route_name(r) + ": '" + *end + "' is not a " +
                           (r.between_zones ? "zone" : "host") + " of zone '" + z.id + "'");
  }
  for (const auto& link : r.links)
    if (!l.links.count(link))
      throw InputError(label, r.line, route_name(r) + ": no link '" + link + "' in the file");
  if (!r.between_zones) return;
  auto bad = [&](const std::string& gw, const Zone& in, const char* which) {
    throw InputError(label, r.line,
                     route_name(r) + ": " + which + "=\"" + gw + "\" is not a host of zone '" +
                         in.id + "'");
  };
  if (!zone_named(l, r.src)->hosts.count(r.gw_src)) bad(r.gw_src, *zone_named(l, r.src), "gw_src");
  if (!zone_named(l, r.dst)->hosts.count(r.gw_dst)) bad(r.gw_dst, *zone_named(l, r.dst), "gw_dst");
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

// The zone's routes as a graph; a route declared twice (a symmetrical one counts both ways) is
// refused: SimGrid ends the process on it.
void route_graph(const Layout& l, int zi, std::map<std::string, std::set<std::string>>& next,
                 std::map<std::string, std::set<std::string>>& prev, const std::string& label) {
  const Zone& z = l.zones[zi];
  for (const auto& r : l.routes) {
    if (r.zone != zi) continue;
    if (z.routing == "None" || z.routing == "Cluster")
      throw InputError(label, r.line,
                       route_name(r) + ": zone '" + z.id + "' (routing " + z.routing +
                           ") takes no routes");
    check_ends(l, r, label);
    if (r.src == r.dst) continue;
    auto add = [&](const std::string& a, const std::string& b) {
      if (!next[a].insert(b).second)
        throw InputError(label, r.line,
                         "a route " + a + " -> " + b + " is declared twice in zone '" + z.id +
                             "' (a symmetrical route declares both directions)");
      prev[b].insert(a);
    };
    add(r.src, r.dst);
    if (r.symmetrical) add(r.dst, r.src);
  }
}

void check_zone(const Layout& l, int zi, const std::string& label) {
  const Zone& z = l.zones[zi];
  std::map<std::string, std::set<std::string>> next, prev;
  route_graph(l, zi, next, prev, label);
  if (z.routing == "None" || z.routing == "Cluster" || z.points.size() < 2) return;
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
  const Layout l = read_layout(xml, label);
  for (int z = 0; z < int(l.zones.size()); ++z)
    check_zone(l, z, label);
}

} // namespace zc
