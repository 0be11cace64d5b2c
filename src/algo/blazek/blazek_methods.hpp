#pragma once
#include <vector>

#include "algo/algorithm.hpp"

namespace zc {
// Blazek 1991, ch. V: host-initiated (--packet N), node-initiated, object-forwarding
// (--forward object|polygons), host-broadcast (--lines strips|interleaved).
std::vector<Algorithm> blazek_algorithms();

// The methods' host (SRM) and node programs, one file each (blazek_<method>.cpp).
namespace blazek {
void host_initiated_host(NodeContext&);
void host_initiated_node(NodeContext&);
void describe_round_robin(NodeContext&); // node initiated's host
void node_initiated_node(NodeContext&);
void object_forwarding_node(NodeContext&);
void host_broadcast_host(NodeContext&);
void host_broadcast_node(NodeContext&);
} // namespace blazek
} // namespace zc
