#pragma once
// Interconnection topologies and their routes. Hypercube: node i is linked to i ^ 2^k over
// channel k, and a message corrects the lowest differing address bit first (e-cube routing, as
// the iPSC DCMs do: Nugent 1988). Ring: node i is linked to i±1 mod P and a message takes the
// shorter way round (clockwise on a tie).
#include <string>
#include <utility>
#include <vector>

namespace zc {

enum class Topology { Cube, Ring };

Topology parse_topology(const std::string& s); // "cube" | "ring", else UsageError
const char* topology_name(Topology t);

// Checks that P nodes can form the topology (a power of two for a cube); throws UsageError.
void check_node_count(Topology t, int nodes);

// The directed channels (from, to) a message from src to dst traverses, in order.
std::vector<std::pair<int, int>> route(Topology t, int nodes, int src, int dst);
// The same route written over `out`, whose capacity is kept (the simulator builds one a message).
void route_into(Topology t, int nodes, int src, int dst, std::vector<std::pair<int, int>>& out);
int hops(Topology t, int nodes, int src, int dst);

// Neighbours of a node: cube channel k -> i ^ 2^k; ring 0 -> i+1, 1 -> i-1. (Inline: the
// simulator numbers every hold's channels with it.)
inline int neighbour(Topology t, int nodes, int node, int channel) {
  if (t == Topology::Cube) return node ^ (1 << channel);
  return channel == 0 ? (node + 1) % nodes : (node + nodes - 1) % nodes;
}
int channel_count(Topology t, int nodes);
int log2_exact(int p); // for a power of two

} // namespace zc
