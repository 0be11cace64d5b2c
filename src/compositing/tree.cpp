// Tree compositing (Blazek 1991's hierarchical merge): at level i the nodes whose rank has bit i
// set and no lower bit send their whole picture to rank - 2^i, which merges it; after
// ceil(log2 P) levels node 0 holds the final picture. Every message carries the whole screen
// held, so the volume per level does not shrink as in binary swap.
#include "compositing/strategy.hpp"

namespace zc::compositing {

namespace {

Measures tree_composite(Node& n, Picture& p, const std::vector<int>& owner) {
  Comm& c = n.comm;
  const int r = c.rank(), P = c.size();
  Measures m;
  for (int bit = 1, level = 0; bit < P; bit <<= 1, ++level) {
    if (r & (bit - 1)) break; // sent its picture at an earlier level
    const bool sends = r & bit;
    const int partner = sends ? r - bit : r + bit;
    if (!sends && partner >= P) continue;
    std::vector<int> dest(owner.size(), sends ? partner : r);
    std::vector<Message> out = p.split({dest, r, P, sends ? 0 : 1}, Merge::Lists, n);
    std::vector<Message> in;
    if (sends) {
      m.step_bytes.push_back(double(out[std::size_t(partner)].charged));
      c.send(partner, kTreeTag + level, std::move(out[std::size_t(partner)]));
    } else {
      in.push_back(c.recv_message(partner, kTreeTag + level));
    }
    m.merge_load += p.merge(std::move(in), Merge::Lists, n);
    end_round(n);
  }
  return m;
}

} // namespace

Strategy tree() {
  Strategy s;
  s.name = "tree";
  s.summary = "pairwise merges of whole pictures up a binary tree to node 0 (Blazek)";
  s.refuses = [](int) { return std::string(); };
  s.owners = [](int) { return 1; };
  s.composite = tree_composite;
  return s;
}

} // namespace zc::compositing
