// The even split of the screen for pixel merging: the rows halved recursively whatever their
// pixels, Kurc et al.'s unbalanced baseline (and ZBUF-EXC's regions).
#include "algo/kurc/kurc_partition.hpp"

namespace zc {

std::vector<int> even_split(int height, int nodes) {
  // Recursive subdivision with every row weighing the same.
  return recursive_subdivision(std::vector<std::uint64_t>(std::size_t(height), 1), nodes);
}

} // namespace zc
