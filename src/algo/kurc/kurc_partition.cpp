// Kurc, Aykanat, Ozguc §4: the screen partitions by name, and the load measures of Fig. 2.
#include "algo/kurc/kurc_partition.hpp"

#include <algorithm>
#include <numeric>

namespace zc {

const ScreenPartition kRecursiveSubdivision{"rs", recursive_subdivision};
const ScreenPartition kHeuristicBinPacking{"hbp", heuristic_bin_packing};
const ScreenPartition kEvenSplit{"even",
                                 [](const std::vector<std::uint64_t>& row_pixels, int nodes) {
                                   return even_split(int(row_pixels.size()), nodes);
                                 }};

std::vector<std::uint64_t> node_loads(const std::vector<std::uint64_t>& row_pixels,
                                      const std::vector<int>& owner, int nodes) {
  std::vector<std::uint64_t> l(nodes, 0);
  for (std::size_t y = 0; y < owner.size(); ++y)
    l[owner[y]] += row_pixels[y];
  return l;
}

} // namespace zc
