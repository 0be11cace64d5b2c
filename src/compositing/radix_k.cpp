// Radix-k (Peterka, Goodell, Ross, Shen, Thakur 2009): P factored into rounds k_1 x ... x k_r;
// in round j the nodes that differ only in the j-th mixed-radix digit of their rank form a group
// of k_j, which splits its rows k_j ways by the owners' j-th digit and exchanges them all to all
// (one message to each other member), so after the last round each node holds its own rows.
// k = 2 in every round is binary swap (pairwise list merges), one round of k = P direct send
// (rows z-buffered). A group of a power of two is a subcube (group.hpp).
#include "compositing/group.hpp"
#include "compositing/strategy.hpp"

namespace zc::compositing {

std::vector<int> radix_rounds(int nodes, const std::vector<int>& radix) {
  std::vector<int> rounds;
  int left = nodes;
  const bool repeat = radix.size() == 1;
  for (int k : radix) {
    if (k < 2 || (!repeat && left % k != 0)) return {};
    do {
      if (left % k != 0) break;
      rounds.push_back(k);
      left /= k;
    } while (repeat && left > 1);
  }
  if (left > 1) rounds.push_back(left);
  return rounds;
}

namespace {

Measures radix_k_composite(Node& n, Picture& p, const std::vector<int>& owner,
                           const std::vector<int>& radix) {
  const std::vector<int> rounds = radix_rounds(n.comm.size(), radix);
  Measures m;
  std::vector<int> dest(owner.size());
  for (int j = 0, stride = 1; j < int(rounds.size()); stride *= rounds[std::size_t(j)], ++j) {
    const int k = rounds[std::size_t(j)];
    GroupComm group(n.comm, digit_group(n.comm.rank(), rounds, j));
    Node g{group, n.memory, n.work, n.charge_round};
    // The member of this round's group whose digit j is the owner's.
    for (std::size_t y = 0; y < owner.size(); ++y)
      dest[y] = owner[y] < 0 ? -1 : (owner[y] / stride) % k;
    exchange(g, group, p, dest, k == 2 ? Merge::Lists : Merge::Zbuffer, m);
  }
  return m;
}

} // namespace

Strategy radix_k(std::vector<int> radix) {
  Strategy s;
  s.name = "radix-k";
  s.summary = "rounds of all-to-all exchanges within groups of k (Peterka et al. 2009)";
  s.refuses = [radix](int nodes) {
    return nodes == 1 || !radix_rounds(nodes, radix).empty()
               ? std::string()
               : "--radix: a k of at least 2, or factors of at least 2 each dividing the node "
                 "count " +
                     std::to_string(nodes);
  };
  s.owners = [](int nodes) { return nodes; };
  s.composite = [radix](Node& n, Picture& p, const std::vector<int>& owner) {
    return radix_k_composite(n, p, owner, radix);
  };
  return s;
}

} // namespace zc::compositing
