#pragma once
#include <vector>

#include "algo/algorithm.hpp"

namespace zc {
// Blazek 1991, ch. V: host-initiated (--packet N), node-initiated, object-forwarding
// (--forward object|polygons), host-broadcast (--lines strips|interleaved).
std::vector<Algorithm> blazek_algorithms();
} // namespace zc
