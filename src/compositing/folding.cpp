// Binary-swap folding (as IceT's bswap.c composites a number of nodes that is not a power of
// two): the P - P' nodes above the largest power of two P' <= P each send their whole picture to
// node r - P', which merges it; then binary swap among the first P'. The region's owners are the
// first P' nodes; the folded ones end with no rows.
#include "compositing/group.hpp"
#include "compositing/strategy.hpp"

namespace zc::compositing {

namespace {

int power_below(int nodes) {
  int p = 1;
  while (2 * p <= nodes)
    p *= 2;
  return p;
}

Measures folding_composite(Node& n, Picture& p, const std::vector<int>& owner) {
  Comm& c = n.comm;
  const int r = c.rank(), P = c.size(), low = power_below(P);
  Measures m;
  const bool folded = r >= low, receives = r + low < P;
  if (folded || receives) {
    const int partner = folded ? r - low : r + low;
    std::vector<int> dest(owner.size(), folded ? partner : r);
    std::vector<Message> out = p.split({dest, r, P, folded ? 0 : 1}, Merge::Lists, n);
    std::vector<Message> in;
    if (folded) {
      m.step_bytes.push_back(double(out[std::size_t(partner)].charged));
      c.send(partner, kFoldingTag, std::move(out[std::size_t(partner)]));
    } else {
      in.push_back(c.recv_message(partner, kFoldingTag));
    }
    m.merge_load += p.merge(std::move(in), Merge::Lists, n);
    end_round(n);
  }
  if (folded) return m;
  std::vector<int> members(static_cast<std::size_t>(low));
  for (int k = 0; k < low; ++k)
    members[std::size_t(k)] = k;
  GroupComm group(c, members);
  Node g{group, n.memory, n.work, n.charge_round};
  Measures swap = binary_swap().composite(g, p, owner);
  m.step_bytes.insert(m.step_bytes.end(), swap.step_bytes.begin(), swap.step_bytes.end());
  m.merge_load += swap.merge_load;
  return m;
}

} // namespace

Strategy folding() {
  Strategy s;
  s.name = "folding";
  s.summary = "binary swap after folding the nodes above a power of two onto those below";
  s.refuses = [](int) { return std::string(); };
  s.owners = power_below;
  s.composite = folding_composite;
  return s;
}

} // namespace zc::compositing
