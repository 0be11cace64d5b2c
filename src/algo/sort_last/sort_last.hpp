#pragma once
#include "algo/algorithm.hpp"

namespace zc {
// Sort-last object-space rendering followed by one compositing strategy of src/compositing:
// Kurc et al.'s first two phases (triangles dealt round-robin, span lists, local z-buffer into
// the representation --picture names), then the strategy over a region of the screen shared by
// heuristic bin packing of the active pixels (Kurc et al. §4.2) or, for a dense picture, in equal
// strips; node 0 gathers the picture. Names: sort-last-<strategy> (compositing::strategies()).
std::vector<Algorithm> sort_last_algorithms();
} // namespace zc
