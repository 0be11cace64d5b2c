#pragma once
#include "algo/algorithm.hpp"

namespace zc {
// The classic communication benchmark of these machines: node `from` sends m bytes to node `to`,
// which answers with m bytes, for every size; the report's metrics list the one-way times.
// Options: from, to (comma-separated nodes; -1 = every other node), sizes (comma-separated bytes).
Algorithm pingpong_algorithm();
} // namespace zc
