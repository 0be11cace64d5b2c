// One exchange within a group, shared by direct send and radix-k: each node's rows go to the
// group rank routed, by the pairwise schedule of the all-to-all (step s: rank r with r XOR s on a
// subcube, r + s on any other group), and every message that arrives is merged.
#include "comm/collectives.hpp"
#include "compositing/strategy.hpp"

namespace zc::compositing {

void exchange(Node& n, Comm& group, Picture& p, const std::vector<int>& dest, Merge how,
              Measures& m) {
  const int P = group.size(), r = group.rank();
  std::vector<Message> out = p.split({dest, r, P, P - 1}, how, n);
  const bool cube = group.topology() == Topology::Cube;
  for (int s = 1; s < P; ++s)
    m.step_bytes.push_back(double(out[std::size_t(cube ? r ^ s : (r + s) % P)].charged));
  auto msgs = coll::alltoallv(group, std::move(out), coll::AllToAll::Pairwise);
  std::vector<Message> in;
  for (int k = 0; k < P; ++k)
    if (k != r) in.push_back(std::move(msgs[std::size_t(k)]));
  m.merge_load += p.merge(std::move(in), how, n);
  end_round(n);
}

} // namespace zc::compositing
