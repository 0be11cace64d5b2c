// Kurc, Aykanat, Ozguc §4.2: heuristic bin packing of the scanlines for pixel merging.
#include <algorithm>
#include <numeric>

#include "algo/kurc_partition.hpp"

namespace zc {

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

} // namespace zc
