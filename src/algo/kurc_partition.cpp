#include "algo/merge_partition.hpp"

#include <algorithm>
#include <numeric>

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

int log2_exact(int p) {
  int d = 0;
  while ((1 << d) < p)
    ++d;
  return d;
}

} // namespace

std::vector<int> even_split(int height, int nodes) {
  std::vector<int> owner(height, 0);
  split(std::vector<std::uint64_t>(height, 1), 0, height, 0, log2_exact(nodes), 0, owner);
  return owner;
}

std::vector<int> recursive_subdivision(const std::vector<std::uint64_t>& row_pixels, int nodes) {
  std::vector<int> owner(row_pixels.size(), 0);
  split(row_pixels, 0, int(row_pixels.size()), 0, log2_exact(nodes), 0, owner);
  return owner;
}

std::vector<int> heuristic_bin_packing(const std::vector<std::uint64_t>& row_pixels, int nodes) {
  std::vector<int> order(row_pixels.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return row_pixels[a] > row_pixels[b]; });
  std::vector<std::uint64_t> load(nodes, 0);
  std::vector<int> owner(row_pixels.size(), 0);
  for (int y : order) {
    const int n = int(std::min_element(load.begin(), load.end()) - load.begin());
    owner[y] = n;
    load[n] += row_pixels[y];
  }
  return owner;
}

std::vector<std::uint64_t> node_loads(const std::vector<std::uint64_t>& row_pixels,
                                      const std::vector<int>& owner, int nodes) {
  std::vector<std::uint64_t> l(nodes, 0);
  for (std::size_t y = 0; y < owner.size(); ++y)
    l[owner[y]] += row_pixels[y];
  return l;
}

double load_imbalance(const std::vector<std::uint64_t>& loads) {
  if (loads.empty()) return 0;
  const auto [mn, mx] = std::minmax_element(loads.begin(), loads.end());
  const double avg =
      double(std::accumulate(loads.begin(), loads.end(), std::uint64_t(0))) / double(loads.size());
  return avg > 0 ? double(*mx - *mn) / avg : 0.0;
}

} // namespace zc
