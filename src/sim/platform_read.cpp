// Reading a loaded platform back as zcube's model of it (read_platform): the zone's zcube.*
// properties, the nodes and their routes, the links' figures, the start-up SMPI would charge, the
// node memory and the CPU costs; every figure checked against the simulated clock's bounds.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include <xbt/config.hpp>

#include "machine/clock_limits.hpp"
#include "machine/platform_xml.hpp"
#include "machine/units.hpp"
#include "sim/platform_load.hpp"
#include "sim/platform_routes.hpp"
#include "util/error.hpp"
#include "util/error_text.hpp"

namespace zc {

namespace sg = simgrid::s4u;

namespace {

// A finite number >= lo (> lo when strict); `what` names the attribute in the error.
double checked(double v, const std::string& where, const std::string& what, double lo = 0,
               bool strict = false) {
  if (!std::isfinite(v) || v < lo || (strict && v == lo))
    throw InputError(where, 0,
                     what + " = " + format_double(v) + ": expected a finite number " +
                         (strict ? "> " : ">= ") + format_double(lo));
  return v;
}

// A link's figures within the clock's bounds (machine/clock_limits.hpp).
double clock_safe_delay(double v, const std::string& where, const std::string& what) {
  if (v > kMaxDelay_s)
    throw InputError(where, 0,
                     what + " = " + format_double(v) +
                         " s: above 1 h; slower costs push the simulated clock past 2^52 ns, "
                         "where compute times are rounded");
  return v;
}

double clock_safe_bandwidth(double v, const std::string& where, const std::string& what) {
  if (v < kMinBandwidth_Bps)
    throw InputError(where, 0,
                     what + " = " + format_double(v) +
                         " Bps: below 1 Bps; slower links push the simulated clock past 2^52 ns, "
                         "where compute times are rounded");
  return v;
}

double number(const std::string& text, const std::string& where, const std::string& what) {
  char* end = nullptr;
  const double d = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(d))
    throw InputError(where, 0, what + " = '" + text + "': expected a finite number");
  return d;
}

// smpi/or "size:offset:factor;...": zcube reads one constant offset per protocol, the short one
// from size 0 and the long one above the second section's size.
void read_startup(const std::string& text, const std::string& where, const std::string& what,
                  NetworkParams& n, double& short_overhead, double& long_overhead) {
  std::vector<std::array<double, 3>> sections;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t semi = std::min(text.find(';', at), text.size());
    const std::string s = text.substr(at, semi - at);
    const auto c1 = s.find(':'), c2 = s.find(':', c1 == s.npos ? s.size() : c1 + 1);
    if (c1 == s.npos || c2 == s.npos)
      throw InputError(where, 0, what + " section '" + s + "': expected size:offset:factor");
    sections.push_back({number(s.substr(0, c1), where, what + " size"),
                        number(s.substr(c1 + 1, c2 - c1 - 1), where, what + " offset"),
                        number(s.substr(c2 + 1), where, what + " factor")});
    at = semi + 1;
  }
  if (sections.size() > 2 || sections[0][0] != 0)
    throw InputError(where, 0,
                     what + " = '" + text +
                         "': zcube reads one section from size 0 and at most one more (the long "
                         "protocol)");
  for (const auto& s : sections) {
    clock_safe_delay(checked(s[1], where, what + " offset"), where, what + " offset");
    if (s[2] != 0) throw InputError(where, 0, what + " factor: zcube reads 0 only");
  }
  short_overhead = sections[0][1];
  long_overhead = sections.back()[1];
  n.short_max_bytes = sections.size() == 2 ? checked(sections[1][0], where, what + " size") : 100;
}

int count_nodes(const sg::Engine& e, const std::string& where) {
  int P = 0;
  while (e.host_by_name_or_null(node_host_name(P)))
    ++P;
  if (P == 0) throw InputError(where, 0, "no host node0: not a zcube platform");
  if (!e.host_by_name_or_null(kHostComputerName))
    throw InputError(where, 0, std::string("host '") + kHostComputerName + "' is missing");
  if (int(e.get_host_count()) != P + 1)
    throw InputError(where, 0,
                     std::string("hosts must be node0..nodeP-1 and ") + kHostComputerName);
  return P;
}

// The channels of SimGrid's route from `a` to `b` (a duplex link rides under a channel: it adds no
// hop); the route's links in `links`.
int channels_on_route(const sg::Host* a, const sg::Host* b, std::vector<sg::Link*>& links,
                      const std::string& where) {
  links.clear();
  try {
    a->route_to(b, links, nullptr);
  } catch (const std::exception& ex) {
    throw InputError(
        where, 0, "route " + a->get_name() + " -> " + b->get_name() + ": " + one_line(ex.what()));
  }
  return int(std::count_if(links.begin(), links.end(), [](const sg::Link* l) {
    return !is_duplex_link(l->get_name()) && l->get_name().find("loopback") == std::string::npos;
  }));
}

// The file's routes must be the topology's: hop counts from node0 and back (e-cube on the cube),
// and the host link alone between node0 and the host, each way. The declared routes were checked
// before SimGrid computed any (sim/platform_routes.hpp), so every route exists.
void check_routes(const sg::Engine& e, const PlatformModel& m, const std::string& where) {
  const sg::Host* node0 = e.host_by_name(node_host_name(0));
  std::vector<sg::Link*> links;
  for (int r = 1; r < m.nodes; ++r) {
    const sg::Host* other = e.host_by_name(node_host_name(r));
    const int want = hops(m.topology, m.nodes, 0, r);
    for (const bool out : {true, false}) {
      const int channels = out ? channels_on_route(node0, other, links, where)
                               : channels_on_route(other, node0, links, where);
      if (channels != want)
        throw InputError(
            where, 0,
            "route " + (out ? "node0 -> " + node_host_name(r) : node_host_name(r) + " -> node0") +
                " has " + std::to_string(channels) + " channels, a " + topology_name(m.topology) +
                " of " + std::to_string(m.nodes) + " nodes has " + std::to_string(want));
    }
  }
  const sg::Host* host = e.host_by_name(kHostComputerName);
  for (const bool up : {true, false}) {
    if (up)
      channels_on_route(node0, host, links, where);
    else
      channels_on_route(host, node0, links, where);
    const std::string want = up ? kHostUpLink : kHostDownLink;
    std::erase_if(links, [](const sg::Link* l) {
      return l->get_name().find("loopback") != std::string::npos;
    });
    if (links.size() != 1 || links[0]->get_name() != want)
      throw InputError(where, 0,
                       std::string("route ") + (up ? "node0 -> " : "") + kHostComputerName +
                           (up ? "" : " -> node0") + ": expected the link '" + want +
                           "' alone (the host is linked to node 0)");
  }
}

struct LinkFigures {
  std::string name;
  double bw, lat;
  bool operator==(const LinkFigures& o) const { return bw == o.bw && lat == o.lat; }
};

// zcube models identical channels: the figures most links of a kind share, and the first link
// that differs from them is the one named (an edit of one link names that link).
LinkFigures common_figures(const std::vector<LinkFigures>& links, const std::string& kind,
                           const std::string& where) {
  // Counted in one pass (a 1024-node cube has 20,480 channels); ties go to the first link.
  std::map<std::pair<double, double>, std::size_t> count;
  for (const auto& l : links)
    ++count[{l.bw, l.lat}];
  std::size_t best = 0, best_count = 0;
  for (std::size_t i = 0; i < links.size(); ++i)
    if (const std::size_t c = count[{links[i].bw, links[i].lat}]; c > best_count)
      best = i, best_count = c;
  for (const auto& l : links)
    if (!(l == links[best]))
      throw InputError(where, 0,
                       "link '" + l.name + "' (bandwidth " + format_double(l.bw) +
                           " Bps, latency " + format_double(l.lat) + " s) differs from the other " +
                           kind + " (" + format_double(links[best].bw) + " Bps, " +
                           format_double(links[best].lat) + " s): zcube models identical channels");
  return links[best];
}

// A channel's bandwidth or latency, checked as checked() and clock_safe_*() check it; the link is
// named only in the error (a 1024-node cube has 20,000 links).
double link_figure(double v, bool bandwidth, const std::string& name, const std::string& where) {
  if (std::isfinite(v) && (bandwidth ? v >= kMinBandwidth_Bps : v >= 0 && v <= kMaxDelay_s))
    return v;
  const std::string what = "link '" + name + "' " + (bandwidth ? "bandwidth" : "latency");
  return bandwidth ? clock_safe_bandwidth(checked(v, where, what, 0, true), where, what)
                   : clock_safe_delay(checked(v, where, what), where, what);
}

void read_links(const sg::Engine& e, const std::string& where, NetworkParams& n) {
  std::vector<LinkFigures> channels, host, duplex;
  for (const sg::Link* l : e.get_all_links()) {
    const std::string& name = l->get_name();
    if (name == "__loopback__") continue;
    if (is_duplex_link(name)) { // the two-way total: no latency of its own
      const std::string what = "link '" + name + "' ";
      const double bw = checked(l->get_bandwidth(), where, what + "bandwidth", 0, true);
      if (l->get_latency() != 0)
        throw InputError(where, 0, what + "latency: a duplex link adds no latency (0s)");
      duplex.push_back({name, bw, 0});
      continue;
    }
    const double bw = link_figure(l->get_bandwidth(), true, name, where);
    const double lat = link_figure(l->get_latency(), false, name, where);
    (name == kHostUpLink || name == kHostDownLink ? host : channels).push_back({name, bw, lat});
  }
  if (host.empty())
    throw InputError(where, 0, std::string("link '") + kHostUpLink + "' is missing");
  const LinkFigures h = common_figures(host, "host link", where);
  n.host_per_byte_s = 1.0 / h.bw;
  n.host_startup_s = h.lat;
  if (!channels.empty()) {
    const LinkFigures c = common_figures(channels, "channels", where);
    n.per_byte_s = 1.0 / c.bw;
    n.per_hop_s = c.lat;
  }
  if (!duplex.empty()) n.both_ways_Bps = common_figures(duplex, "duplex links", where).bw;
}

// SMPI's receive overhead as SMPI finds it: the host's smpi/or property, else the global setting
// (files written before the property carry it in <config>). zcube models identical nodes.
std::pair<std::string, std::string> startup_text(const sg::Engine& e, int nodes,
                                                 const std::string& where) {
  const char* first = e.host_by_name(node_host_name(0))->get_property(kStartupProperty);
  for (int r = 1; r < nodes; ++r) {
    const char* v = e.host_by_name(node_host_name(r))->get_property(kStartupProperty);
    if ((v == nullptr) != (first == nullptr) || (v && std::string(v) != first))
      throw InputError(where, 0,
                       "host '" + node_host_name(r) + "' property " + kStartupProperty +
                           " differs from node0's: zcube models identical nodes");
  }
  if (first) return {first, "host property " + std::string(kStartupProperty)};
  return {simgrid::config::get_value<std::string>(kStartupConfig),
          "<config> " + std::string(kStartupConfig)};
}

const char* zone_prop(const sg::NetZone* z, const std::string& key, const std::string& where) {
  const char* v = z->get_property(key);
  if (!v) throw InputError(where, 0, "zone property '" + key + "' is missing");
  return v;
}

// The node memory (returned), the operating system's resident share and what a message is
// charged, from the zone's properties.
double read_memory(const sg::NetZone* z, const std::string& where, PlatformModel& m) {
  // A size without a unit is refused, as on the command line (a bare "4" would be 4 bytes).
  const double memory = parse_bytes(zone_prop(z, "zcube.node_memory", where),
                                    where + ": zcube.node_memory", Unit::Required);
  checked(memory, where, "zcube.node_memory", 0, true);
  if (memory > kMaxNodeMemory_bytes)
    throw InputError(where, 0,
                     "zcube.node_memory = " + format_double(memory) +
                         " bytes: above 1 PiB, where a node's byte counts lose precision");
  // The node operating system's resident size (docs/memory.md); files without it: none.
  if (const char* os = z->get_property("zcube.os_resident")) {
    m.os_resident = parse_bytes(os, where + ": zcube.os_resident", Unit::Required);
    checked(m.os_resident, where, "zcube.os_resident", 0, false);
    if (m.os_resident > memory)
      throw InputError(where, 0,
                       "zcube.os_resident = " + format_double(m.os_resident) +
                           " bytes: more than the node's memory (zcube.node_memory, " +
                           format_double(memory) + " bytes)");
  }
  // What a message is charged (NetworkParams::charge_payloads); files without it: the records.
  if (const char* msgs = z->get_property("zcube.messages")) {
    if (std::string(msgs) != "records" && std::string(msgs) != "payloads")
      throw InputError(
          where, 0, "zcube.messages = '" + std::string(msgs) + "': expected records or payloads");
    m.net.charge_payloads = std::string(msgs) == "payloads";
  }
  return memory;
}

// Every node's CPU costs (the zone's cycles over the host's speed) and memory.
void read_costs(const sg::Engine& e, const sg::NetZone* z, const std::string& where, double memory,
                PlatformModel& m) {
  CostTable cycles;
  for (auto& [id, v] : cycles.fields()) {
    const std::string key = "zcube.cycles." + id.substr(5);
    *v = checked(number(zone_prop(z, key, where), where, key), where, key);
  }
  for (int r = 0; r < m.nodes; ++r) {
    const sg::Host* h = e.host_by_name(node_host_name(r));
    const double speed =
        checked(h->get_speed(), where, "host '" + h->get_name() + "' speed", 0, true);
    CostTable seconds = cycles;
    for (auto& [id, v] : seconds.fields()) {
      *v /= speed;
      if (*v > kMaxDelay_s) // held to the clock's bounds, as a link's figures are
        throw InputError(where, 0,
                         "zcube.cycles." + id.substr(5) + " = " + format_double(*v * speed) +
                             " cycles: " + format_double(*v) + " s an operation on host '" +
                             h->get_name() + "', above 1 h; slower costs push the simulated " +
                             "clock past 2^52 ns, where compute times are rounded");
    }
    m.cost.push_back(seconds);
    m.memory.push_back(memory);
  }
}

} // namespace

PlatformModel read_platform(const sg::Engine& e, const std::string& where) {
  e.seal_platform(); // a Dijkstra zone (machines with duplex links) has no routes before its seal
  PlatformModel m;
  const sg::NetZone* z = e.get_netzone_root();
  // The machine zone is the root, or its only child when the file wraps it.
  if (!z->get_property("zcube.machine") && z->get_children().size() == 1) z = z->get_children()[0];
  if (!z->get_property("zcube.machine"))
    throw InputError(where, 0, "not a zcube platform (no zcube.machine property on its zone)");
  m.machine = zone_prop(z, "zcube.machine", where);
  const std::string topology = zone_prop(z, "zcube.topology", where);
  if (topology != "cube" && topology != "hypercube" && topology != "ring")
    throw InputError(where, 0, "zcube.topology = '" + topology + "': expected cube or ring");
  m.topology = parse_topology(topology);
  const std::string sw = zone_prop(z, "zcube.switching", where);
  if (sw != "circuit" && sw != "store-and-forward")
    throw InputError(where, 0,
                     "zcube.switching = '" + sw + "': expected circuit or store-and-forward");
  m.net.switching = sw == "circuit" ? Switching::Circuit : Switching::StoreAndForward;
  m.nodes = count_nodes(e, where);
  try {
    check_node_count(m.topology, m.nodes);
  } catch (const UsageError&) {
    throw InputError(where, 0,
                     "zcube.topology = " + std::string(topology_name(m.topology)) + " with " +
                         std::to_string(m.nodes) + " nodes: a " + topology_name(m.topology) +
                         (m.topology == Topology::Cube ? " needs a power of two up to 1024"
                                                       : " has 1 to 1024 nodes"));
  }
  check_routes(e, m, where);

  read_links(e, where, m.net);
  double short_o = 0, long_o = 0;
  const auto [startup, startup_what] = startup_text(e, m.nodes, where);
  read_startup(startup, where, startup_what, m.net, short_o, long_o);
  // start-up = receive overhead + the first hop's latency + SMPI's envelope at the channel rate.
  const double fixed = m.net.per_hop_s + kSmpiEnvelopeBytes * m.net.per_byte_s;
  m.net.startup_short_s = short_o + fixed;
  m.net.startup_long_s = long_o + fixed;

  const double memory = read_memory(z, where, m);
  read_costs(e, z, where, memory, m);
  return m;
}

} // namespace zc
