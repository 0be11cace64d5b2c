#include "machine/platform_xml.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <set>
#include <sstream>
#include <string>

#include "machine/cpu_model.hpp"
#include "machine/units.hpp"

namespace zc {

std::string node_host_name(int rank) {
  return "node" + std::to_string(rank);
}

std::string platform_file_name(const std::string& machine, int nodes, Topology topology) {
  return machine + (topology == Topology::Ring ? "-ring-" : "-") + std::to_string(nodes) + ".xml";
}

double cpu_clock_hz(const MachineSpec& spec) {
  // Tables without a CPU model (e.g. a probed host): nanoseconds read as cycles of 1 GHz.
  return spec.cpu.empty() ? 1e9 : cpu_model(spec.cpu).clock_hz;
}

namespace {

// Topology parameters of the SimGrid torus: "2,2,...,2" (d times) for a cube of 2^d nodes (a
// single "1" for one node), "P" for a ring.
std::string torus_dimensions(Topology topo, int nodes) {
  if (topo == Topology::Ring || nodes == 1) return std::to_string(nodes);
  std::string d;
  for (int k = 0; k < log2_exact(nodes); ++k)
    d += k ? ",2" : "2";
  return d;
}

// smpi/or: one section per protocol, "size:offset:factor" (SMPI applies a section to messages
// larger than its size). The channel latency and the envelope are charged by SimGrid itself.
// The overhead is chosen so that the reader's sum, overhead + (lat + 16 / bw), is the start-up to
// the bit (sim/platform_load.cpp): a file written with what-ifs times as the flags do.
std::string startup_sections(const NetworkParams& n) {
  auto overhead = [&](double startup) {
    const double fixed = n.per_hop_s + kSmpiEnvelopeBytes * n.per_byte_s;
    const double first = startup - n.per_hop_s - kSmpiEnvelopeBytes * n.per_byte_s;
    double o = first;
    for (int step = 0; step < 64 && o + fixed != startup; ++step)
      o = std::nextafter(o, o + fixed < startup ? HUGE_VAL : -HUGE_VAL);
    return format_double(o + fixed == startup ? o : first);
  };
  return "0:" + overhead(n.startup_short_s) + ":0;" + format_double(n.short_max_bytes) + ":" +
         overhead(n.startup_long_s) + ":0";
}

// The start-up of every node as SMPI reads it from a host: its receive overhead smpi/or.
std::string startup_prop(const NetworkParams& n) {
  return std::string("<prop id=\"") + kStartupProperty + "\" value=\"" + startup_sections(n) +
         "\"/>";
}

// `v` in the largest of SimGrid's unit prefixes, in the fewest digits (at most 12; else plain) that
// SimGrid (which multiplies the number by the prefix) reads back as `exact` would: "16Mf",
// "2.8MBps", "10us".
std::string with_unit(double v, const std::string& unit,
                      std::initializer_list<std::pair<double, const char*>> prefixes,
                      const std::function<bool(double)>& exact) {
  for (auto [scale, prefix] : prefixes) {
    if (v < scale) continue;
    for (int digits = 1; digits <= 12; ++digits) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.*g", digits, v / scale);
      if (std::strchr(buf, 'e')) continue;
      if (exact(std::strtod(buf, nullptr) * scale)) return buf + std::string(prefix) + unit;
    }
  }
  return format_double(v) + unit;
}

std::string with_unit(double v, const std::string& unit,
                      std::initializer_list<std::pair<double, const char*>> prefixes) {
  return with_unit(v, unit, prefixes, [v](double read) { return read == v; });
}

// The channel rate whose inverse is exactly the per-byte cost.
std::string rate(double per_byte_s) {
  if (!(per_byte_s > 0)) return "1e15Bps";
  return with_unit(1.0 / per_byte_s, "Bps", {{1e9, "G"}, {1e6, "M"}, {1e3, "k"}},
                   [per_byte_s](double read) { return 1.0 / read == per_byte_s; });
}

std::string seconds(double s) {
  if (s == 0) return "0s";
  return with_unit(s, "s", {{1, ""}, {1e-3, "m"}, {1e-6, "u"}, {1e-9, "n"}});
}

// The nodes as a zone of their own with one link per direction of each channel and, under each
// pair of directions, a shared link of the two-way total (the T800's 2.35 MB/s both ways busy,
// docs/machines.md): SimGrid's flow model then gives each direction its one-way rate alone and half
// the total with both busy. A TORUS cluster has no such link, so the routes are written out: one
// per neighbour, the rest found by Dijkstra (shortest paths: the topology's hop counts).
void duplex_nodes_zone(std::ostringstream& x, const std::string& id, const NetworkParams& n,
                       const std::string& speed, int nodes, Topology topo) {
  // One node has no channel to route over: a Full zone (SimGrid's Dijkstra crashes on a graph
  // without an edge when a route leaves the zone).
  x << "    <zone id=\"" << id << "\" routing=\"" << (nodes == 1 ? "Full" : "DijkstraCache")
    << "\">\n";
  for (int r = 0; r < nodes; ++r)
    x << "      <host id=\"" << node_host_name(r) << "\" speed=\"" << speed << "\">"
      << startup_prop(n) << "</host>\n";
  std::set<std::pair<int, int>> pairs;
  for (int a = 0; a < nodes; ++a)
    for (int k = 0; k < channel_count(topo, nodes); ++k)
      if (const int b = neighbour(topo, nodes, a, k); a < b) pairs.insert({a, b});
  const std::string lat = seconds(n.per_hop_s);
  // The two-way total as zcube reads it: the link's bandwidth itself.
  const std::string total = with_unit(n.both_ways_Bps, "Bps", {{1e9, "G"}, {1e6, "M"}, {1e3, "k"}});
  auto link = [&](const std::string& name, const std::string& bw, const std::string& latency) {
    x << "      <link id=\"" << name << "\" bandwidth=\"" << bw << "\" latency=\"" << latency
      << "\"/>\n";
  };
  auto channel = [](int a, int b) { return "ch-" + std::to_string(a) + "-" + std::to_string(b); };
  for (auto [a, b] : pairs) {
    link(channel(a, b), rate(n.per_byte_s), lat);
    link(channel(b, a), rate(n.per_byte_s), lat);
    link(duplex_link_name(a, b), total, "0s");
  }
  for (auto [a, b] : pairs)
    for (auto [from, to] : {std::pair{a, b}, std::pair{b, a}})
      x << "      <route src=\"" << node_host_name(from) << "\" dst=\"" << node_host_name(to)
        << "\" symmetrical=\"NO\"><link_ctn id=\"" << channel(from, to) << "\"/><link_ctn id=\""
        << duplex_link_name(a, b) << "\"/></route>\n";
  x << "    </zone>\n";
}

} // namespace

// What SimGrid reads from a file, as its header comment says: a cluster's bw and lat, or (a machine
// whose link directions share a total rate, the Volvox) one link per direction and a shared one.
constexpr const char* kReadsCluster =
    "     SimGrid reads: channel bandwidth and latency (cluster bw, lat; lat is the per-hop\n"
    "     cost), the CPU clock (speed), the host link, and the start-up as SMPI's receive\n"
    "     overhead smpi/or, a property of every node (start-up = smpi/or + lat + 16 envelope\n"
    "     bytes / bw; a section per protocol).\n";
constexpr const char* kReadsDuplexLinks =
    "     SimGrid reads: channel bandwidth and latency (links ch-a-b, one a direction; lat is\n"
    "     the per-hop cost) and the shared link duplex-a-b under both directions, the CPU\n"
    "     clock (speed), the host link, and the start-up as SMPI's receive overhead smpi/or,\n"
    "     a property of every node (start-up = smpi/or + lat + 16 envelope bytes / bw; a\n"
    "     section per protocol).\n";
constexpr const char* kReadsConfig =
    "     <config>: the settings under which SimGrid times a message as zcube does, for any\n"
    "     SimGrid program (s4u or smpirun): CM02 flows without cross-traffic and SMPI's latency\n"
    "     and bandwidth factors 1 (smpirun imposes its own network model, SMPI: CM02 with\n"
    "     those factors), every message eager.\n";

std::string duplex_link_name(int a, int b) {
  return kDuplexLinkPrefix + std::to_string(std::min(a, b)) + "-" + std::to_string(std::max(a, b));
}

std::string platform_xml(const MachineSpec& spec, int nodes, Topology topo,
                         const PlatformEdits& edits) {
  check_node_count(topo, nodes);
  const NetworkParams& n = spec.net;
  const double clock = cpu_clock_hz(spec);
  const std::string speed =
      with_unit(clock / edits.cpu_scale, "f", {{1e9, "G"}, {1e6, "M"}, {1e3, "k"}});
  const std::string zone = spec.name + "-" + topology_name(topo) + "-" + std::to_string(nodes);
  std::ostringstream x;
  auto prop = [&](const std::string& id, const std::string& v) {
    x << "    <prop id=\"" << id << "\" value=\"" << v << "\"/>\n";
  };
  x << "<?xml version='1.0'?>\n"
    << "<!DOCTYPE platform SYSTEM \"https://simgrid.org/simgrid.dtd\">\n"
    << "<!-- " << spec.description << ": " << nodes << " nodes, " << topology_name(topo) << ".\n"
    << "     Written by "
    << (spec.generated_by.empty()
            ? "`zcube platform --machine " + spec.name + " --nodes " + std::to_string(nodes) +
                  " --topology " + topology_name(topo) + "`"
            : spec.generated_by)
    << "; edit it as any SimGrid platform.\n"
    << (n.half_duplex_limited() ? kReadsDuplexLinks : kReadsCluster) << kReadsConfig
    << "     zcube.* properties and their meaning: platforms/README.md. -->\n"
    << "<platform version=\"4.1\">\n"
    << "  <config>\n";
  for (const auto& [key, value] : kFlowConfig)
    x << "    <prop id=\"" << key << "\" value=\"" << value << "\"/>\n";
  x << "  </config>\n"
    << "  <zone id=\"" << zone << "\" routing=\"Full\">\n";
  prop("zcube.machine", spec.name);
  prop("zcube.topology", topology_name(topo));
  prop("zcube.switching", n.switching == Switching::Circuit ? "circuit" : "store-and-forward");
  prop("zcube.node_memory", with_unit(spec.memory_bytes, "B",
                                      {{1073741824.0, "Gi"}, {1048576.0, "Mi"}, {1024.0, "Ki"}}));
  prop("zcube.os_resident", with_unit(spec.os_resident_bytes, "B",
                                      {{1073741824.0, "Gi"}, {1048576.0, "Mi"}, {1024.0, "Ki"}}));
  if (n.charge_payloads) prop("zcube.messages", "payloads");
  CostTable cost = spec.cost;
  for (auto& [id, v] : cost.fields()) // "cost_<field>" -> "zcube.cycles.<field>"
    prop("zcube.cycles." + id.substr(5), format_double(*v * clock));
  if (n.half_duplex_limited())
    duplex_nodes_zone(x, zone + "-nodes", n, speed, nodes, topo);
  else
    x << "    <cluster id=\"" << zone << "-nodes\" topology=\"TORUS\" topo_parameters=\""
      << torus_dimensions(topo, nodes) << "\" prefix=\"node\" radical=\"0-" << nodes - 1
      << "\" suffix=\"\" speed=\"" << speed << "\" bw=\"" << rate(n.per_byte_s) << "\" lat=\""
      << seconds(n.per_hop_s) << "\" sharing_policy=\"SPLITDUPLEX\">\n      " << startup_prop(n)
      << "\n    </cluster>\n";
  x << "    <zone id=\"" << zone << "-host\" routing=\"None\">\n"
    << "      <host id=\"" << kHostComputerName << "\" speed=\"" << speed << "\"/>\n"
    << "    </zone>\n";
  for (const char* l : {kHostUpLink, kHostDownLink})
    x << "    <link id=\"" << l << "\" bandwidth=\"" << rate(n.host_per_byte_s) << "\" latency=\""
      << seconds(n.host_startup_s) << "\"/>\n";
  auto zone_route = [&](const std::string& a, const std::string& b, const char* ga, const char* gb,
                        const char* link) {
    x << "    <zoneRoute src=\"" << zone << a << "\" dst=\"" << zone << b << "\" gw_src=\"" << ga
      << "\" gw_dst=\"" << gb << "\" symmetrical=\"NO\"><link_ctn id=\"" << link
      << "\"/></zoneRoute>\n";
  };
  zone_route("-nodes", "-host", "node0", kHostComputerName, kHostUpLink);
  zone_route("-host", "-nodes", kHostComputerName, "node0", kHostDownLink);
  x << "  </zone>\n</platform>\n";
  return x.str();
}

} // namespace zc
