#pragma once
#include "algo/algorithm.hpp"

namespace zc {
// compositing-study: one sort-last rendering (Kurc et al.'s deal, span lists and modified scanline
// z-buffer) and the scanline counts summed once (§4.1, phase "share"), then every compositing
// contender in turn from the same local pictures, each after a barrier and timed as a phase of its
// own (its share of the screen, then the strategy): Kurc et al.'s PAIR-RS and AAPC-HBP on the
// winning pixel array, and binary swap, direct send, radix-k for each k dividing P and binary-swap
// folding on IceT's run-length encoded pixels, shared by heuristic bin packing (§4.2). `zcube
// reproduce compositing` (results/compositing).
std::vector<Algorithm> compositing_study_algorithms();
// The contenders' phase names on P nodes, in the order they run.
std::vector<std::string> compositing_contenders(int nodes);
} // namespace zc
