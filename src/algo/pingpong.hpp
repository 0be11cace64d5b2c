#pragma once
#include "algo/algorithm.hpp"

namespace zc {
// The classic communication benchmark of these machines: node `from` sends m bytes to node `to`,
// which answers with m bytes, for every size; the report's metrics list the one-way times.
// Options: from, to (-1 = every node), sizes (comma-separated bytes), repeats.
Algorithm pingpong_algorithm();
} // namespace zc
