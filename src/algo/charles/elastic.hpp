#pragma once
#include "algo/algorithm.hpp"

namespace zc {
// Charles, Lefevre, Miguet 1995 (§4-§5): image-space parallel z-buffer with elastic load
// balancing, on the hypercube or the ring. Options: vertices = broadcast (the paper's
// MultiBroadcast of all projected vertices) | request (their §7 future work: each node asks the
// owners for only the vertices its triangles use).
Algorithm elastic_algorithm();
} // namespace zc
