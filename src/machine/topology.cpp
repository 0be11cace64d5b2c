#include "machine/topology.hpp"

#include <bit>

#include "util/error.hpp"

namespace zc {

Topology parse_topology(const std::string& s) {
  if (s == "cube" || s == "hypercube") return Topology::Cube;
  if (s == "ring") return Topology::Ring;
  throw UsageError("--topology '" + s + "': expected cube or ring");
}

const char* topology_name(Topology t) {
  return t == Topology::Cube ? "cube" : "ring";
}

void check_node_count(Topology t, int nodes) {
  if (nodes < 1 || nodes > 1024)
    throw UsageError("--nodes " + std::to_string(nodes) + ": expected 1..1024 nodes");
  if (t == Topology::Cube && !std::has_single_bit(unsigned(nodes)))
    throw UsageError("--nodes " + std::to_string(nodes) +
                     ": a hypercube needs a power of two (1, 2, 4, ..., 1024) nodes");
}

int log2_exact(int p) {
  return std::countr_zero(unsigned(p));
}

std::vector<std::pair<int, int>> route(Topology t, int nodes, int src, int dst) {
  std::vector<std::pair<int, int>> r;
  r.reserve(std::size_t(hops(t, nodes, src, dst))); // one allocation
  route_into(t, nodes, src, dst, r);
  return r;
}

void route_into(Topology t, int nodes, int src, int dst, std::vector<std::pair<int, int>>& r) {
  r.clear();
  if (t == Topology::Cube) {
    int at = src;
    for (unsigned diff = unsigned(src ^ dst); diff; diff &= diff - 1) {
      const int next = at ^ int(diff & -diff); // lowest differing bit first
      r.emplace_back(at, next);
      at = next;
    }
    return;
  }
  const int fwd = ((dst - src) % nodes + nodes) % nodes;
  const int step = (fwd <= nodes - fwd) ? 1 : -1;
  for (int at = src; at != dst;) {
    const int next = ((at + step) % nodes + nodes) % nodes;
    r.emplace_back(at, next);
    at = next;
  }
}

int hops(Topology t, int nodes, int src, int dst) {
  if (t == Topology::Cube) return std::popcount(unsigned(src ^ dst));
  const int fwd = ((dst - src) % nodes + nodes) % nodes;
  return std::min(fwd, nodes - fwd);
}

int channel_count(Topology t, int nodes) {
  if (t == Topology::Cube) return log2_exact(nodes);
  return nodes == 1 ? 0 : (nodes == 2 ? 1 : 2);
}

} // namespace zc
