// Kurc, Aykanat, Ozguc §4.2: heuristic bin packing of the scanlines for pixel merging.
#include <algorithm>
#include <functional>
#include <numeric>

#include "algo/kurc/kurc_partition.hpp"

namespace zc {

std::vector<int> heuristic_bin_packing(const std::vector<std::uint64_t>& row_pixels, int nodes) {
  std::vector<int> order(row_pixels.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return row_pixels[a] > row_pixels[b]; });
  // The least-loaded node first, the lower number on a tie: a min-heap of (load, node).
  using Bin = std::pair<std::uint64_t, int>;
  std::vector<Bin> heap(std::size_t(std::max(nodes, 0)));
  for (int n = 0; n < nodes; ++n)
    heap[std::size_t(n)] = {0, n};
  std::vector<int> owner(row_pixels.size(), 0);
  for (int y : order) {
    std::pop_heap(heap.begin(), heap.end(), std::greater<>());
    owner[y] = heap.back().second;
    heap.back().first += row_pixels[y];
    std::push_heap(heap.begin(), heap.end(), std::greater<>());
  }
  return owner;
}

} // namespace zc
