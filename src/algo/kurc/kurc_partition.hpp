#pragma once
// Kurc, Aykanat, Ozguc §4: how the screen's scanlines are shared among the P = 2^d nodes for the
// pixel merging phase. Every scheme returns owner[y], the node that ends with scanline y; the
// assignment is compatible with the pairwise exchange of §3.1, whose stage i splits each node's
// current region between the two subcubes over channel i (bit i of the node number).
#include <cstdint>
#include <vector>

namespace zc {

// Even split: halve the rows recursively (top half to bit-0 = 0, then bit 1, ...): the
// unbalanced baseline.
std::vector<int> even_split(int height, int nodes);

// §4.1 recursive adaptive subdivision: split the rows into two bands of (nearly) equal active
// pixel counts, top band to the subcube with bit i = 0, and recurse on each subcube for bit i+1.
std::vector<int> recursive_subdivision(const std::vector<std::uint64_t>& row_pixels, int nodes);

// §4.2 heuristic bin packing: scanlines in decreasing pixel count (ties: lower y first) each go
// to the least-loaded node (ties: lower node number).
std::vector<int> heuristic_bin_packing(const std::vector<std::uint64_t>& row_pixels, int nodes);

// The one interface of the three: owner[y] from the machine-wide count of active pixels per
// scanline (the even split reads only how many scanlines there are).
struct ScreenPartition {
  const char* name; // the paper's abbreviation, lower case: "rs", "hbp", "even"
  std::vector<int> (*owners)(const std::vector<std::uint64_t>& row_pixels, int nodes);
};
extern const ScreenPartition kRecursiveSubdivision, kHeuristicBinPacking, kEvenSplit;

// Per-node sum of row_pixels under an assignment.
std::vector<std::uint64_t> node_loads(const std::vector<std::uint64_t>& row_pixels,
                                      const std::vector<int>& owner, int nodes);

} // namespace zc
