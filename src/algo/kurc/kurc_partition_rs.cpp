// Kurc, Aykanat, Ozguc §4.1: recursive adaptive subdivision of the screen for pixel merging.
#include "algo/kurc/kurc_partition.hpp"

namespace zc {
namespace {

// Splits rows [a, b) for the nodes whose low `bit` bits equal `prefix`, by weights w.
void split(const std::vector<std::uint64_t>& w, int a, int b, int bit, int dims, int prefix,
           std::vector<int>& owner) {
  if (bit == dims) {
    for (int y = a; y < b; ++y)
      owner[y] = prefix;
    return;
  }
  std::uint64_t total = 0;
  for (int y = a; y < b; ++y)
    total += w[y];
  // Cut c in [a, b] minimising |2*sum[a,c) - total| (ties: lower c).
  int c = a;
  if (total == 0) {
    c = a + (b - a) / 2;
  } else {
    std::uint64_t s = 0, best = total;
    for (int y = a; y <= b; ++y) {
      const std::uint64_t d = 2 * s > total ? 2 * s - total : total - 2 * s;
      if (d < best) {
        best = d;
        c = y;
      }
      if (y < b) s += w[y];
    }
  }
  split(w, a, c, bit + 1, dims, prefix, owner);
  split(w, c, b, bit + 1, dims, prefix | (1 << bit), owner);
}

int ceil_log2(int p) {
  int d = 0;
  while ((1 << d) < p)
    ++d;
  return d;
}

} // namespace

std::vector<int> recursive_subdivision(const std::vector<std::uint64_t>& row_pixels, int nodes) {
  std::vector<int> owner(row_pixels.size(), 0);
  split(row_pixels, 0, int(row_pixels.size()), 0, ceil_log2(nodes), 0, owner);
  return owner;
}

} // namespace zc
