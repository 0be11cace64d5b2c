#pragma once
// Compositing strategies, one file each (docs/compositing.md), all of one shape: every node of a
// group (n.comm) calls `composite` with its partial picture and the same region, owner[y] the
// group rank that ends with row y (-1: nobody's); the picture then holds the final pixels of the
// rows the region gives its node (none for a node that owns none).
#include <functional>
#include <string>
#include <vector>

#include "compositing/picture.hpp"

namespace zc::compositing {

struct Strategy {
  std::string name; // as algorithms and reports name it: "binary-swap"
  std::string summary;
  // The group sizes it composites, and why not when it does not (empty: it does).
  std::function<std::string(int nodes)> refuses;
  // How many nodes own rows at the end: the region's owners are group ranks below it.
  std::function<int(int nodes)> owners;
  std::function<Measures(Node& n, Picture& p, const std::vector<int>& owner)> composite;
};

Strategy binary_swap(); // binary_swap.cpp: log2 P pairwise exchanges (Kurc et al.'s PAIR)
Strategy direct_send(); // direct_send.cpp: every row straight to its owner (AAPC)
Strategy radix_k(std::vector<int> radix); // radix_k.cpp: rounds of groups of k (Peterka et al.)
Strategy folding(); // folding.cpp: binary swap after folding the nodes above a power of two
Strategy tree();    // tree.cpp: pairwise merges up a binary tree to node 0 (Blazek)

// The rounds radix-k makes on P nodes, their product P: a single k repeated as long as it divides
// what is left, or a list of factors in order; what is left as a last round (k = P: direct
// send). Empty when a radix is below 2 or a factor of a list does not divide what is left.
std::vector<int> radix_rounds(int nodes, const std::vector<int>& radix);

// Every strategy with its default parameters (radix-k: k = 4), for the registry and the tests.
std::vector<Strategy> strategies();

// One exchange within a group (direct send, a radix-k round): out[k] to group rank k by the
// pairwise schedule of coll::alltoallv, what arrives merged; bytes of each step into m.
void exchange(Node& n, Comm& group, Picture& p, const std::vector<int>& dest, Merge how,
              Measures& m);

// Tags at and above kTagBase are the compositing layer's (below the collectives'): a strategy's
// messages are told apart from any other's by its own range.
constexpr int kTagBase = 1 << 16;
constexpr int kBinarySwapTag = kTagBase;   // + the stage (at most 63)
constexpr int kFoldingTag = kTagBase + 64; // the fold onto a power of two
constexpr int kTreeTag = kTagBase + 128;   // + the tree level

} // namespace zc::compositing
