// Binary swap (Ma, Painter, Hansen, Krogh 1994; Kurc, Aykanat, Ozguc §3.1's pairwise exchange,
// PAIR; with dense pictures and the even halving of the screen, their full z-buffer merging
// ZBUF-EXC): log2 P stages; at stage i a node keeps the rows whose owner agrees with it on bit i,
// sends the others to its neighbour over channel i and merges what arrives (two x-sorted lists
// into one). The nodes must be a power of two (folding.cpp composites any number).
#include <bit>

#include "compositing/group.hpp"
#include "compositing/strategy.hpp"

namespace zc::compositing {

namespace {

Measures binary_swap_composite(Node& n, Picture& p, const std::vector<int>& owner) {
  Comm& c = n.comm;
  const int r = c.rank();
  Measures m;
  std::vector<int> dest(owner.size());
  for (int bit = 1, stage = 0; bit < c.size(); bit <<= 1, ++stage) {
    // The pair as a group of two: rank 0 the node with bit i clear (it keeps the rows whose owner
    // has bit i clear), rank 1 the other.
    GroupComm pair(c, {r & ~bit, r | bit});
    const int self = pair.rank(), partner = 1 - self;
    for (std::size_t y = 0; y < owner.size(); ++y)
      dest[y] = owner[y] < 0 ? -1 : (owner[y] & bit) ? 1 : 0;
    std::vector<Message> out = p.split({dest, self, 2, 1}, Merge::Lists, n);
    m.step_bytes.push_back(double(out[std::size_t(partner)].charged));
    auto h = pair.isend(partner, kBinarySwapTag + stage, std::move(out[std::size_t(partner)]));
    std::vector<Message> in;
    in.push_back(pair.recv_message(partner, kBinarySwapTag + stage));
    h->wait();
    m.merge_load += p.merge(std::move(in), Merge::Lists, n);
    end_round(n);
  }
  return m;
}

} // namespace

Strategy binary_swap() {
  Strategy s;
  s.name = "binary-swap";
  s.summary = "log2 P pairwise exchanges of half the rows held (Kurc et al.'s PAIR)";
  s.refuses = [](int nodes) {
    return std::has_single_bit(unsigned(nodes))
               ? std::string()
               : "binary swap needs a power of two nodes (folding does not)";
  };
  s.owners = [](int nodes) { return nodes; };
  s.composite = binary_swap_composite;
  return s;
}

} // namespace zc::compositing
