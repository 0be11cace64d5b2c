#pragma once
#include "algo/algorithm.hpp"

namespace zc {
// Kurc, Aykanat, Ozguc, "Active pixel merging on hypercube multicomputers": object-space
// parallel rendering with the modified scanline z-buffer (§2) and pixel merging by pairwise
// exchange (PAIR, §3.1) or all-to-all personalised communication (AAPC, §3.2), the screen shared
// for merging by recursive adaptive subdivision (RS, §4.1), heuristic bin packing (HBP, §4.2) or
// an even split; and full z-buffer merging (ZBUF-EXC), the paper's baseline.
// Names: zbuf-exc, pair-rs, pair-hbp, pair-even, aapc-rs, aapc-hbp, aapc-even.
std::vector<Algorithm> kurc_algorithms();
} // namespace zc
