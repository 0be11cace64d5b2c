#pragma once
#include "algo/algorithm.hpp"

namespace zc {
// Kurc et al.'s one-node reference (algorithm `scanline`): node 0 runs "a sequential rendering
// algorithm for its local polygons" (§1) with every polygon local, i.e. the modified scanline
// z-buffer of §2 (span lists, then the WPA through the MSA) and no pixel merging. Unlike
// `sequential` it holds no full frame buffer, so it fits one 4 MB iPSC/2 node (docs/papers.md).
Algorithm kurc_scanline_algorithm();
} // namespace zc
