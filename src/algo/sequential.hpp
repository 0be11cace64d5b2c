#pragma once
#include "algo/algorithm.hpp"

namespace zc {
// The reference: node 0 renders every frame alone with the scanline z-buffer; speed-ups are
// measured against it (docs/papers.md).
Algorithm sequential_algorithm();
} // namespace zc
