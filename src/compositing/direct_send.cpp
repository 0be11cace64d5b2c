// Direct send (Hsu 1993; Kurc, Aykanat, Ozguc §3.2's all-to-all personalised communication,
// AAPC): every node sends each row it holds straight to the row's owner, by the pairwise schedule
// over disjoint e-cube paths on a hypercube (Abali et al., as §3.2 cites), and each owner
// z-buffers what it receives into its rows. One round, P - 1 messages a node.
#include "compositing/strategy.hpp"

namespace zc::compositing {

Strategy direct_send() {
  Strategy s;
  s.name = "direct-send";
  s.summary = "every row straight to its owner (Kurc et al.'s AAPC)";
  s.refuses = [](int) { return std::string(); };
  s.owners = [](int nodes) { return nodes; };
  s.composite = [](Node& n, Picture& p, const std::vector<int>& owner) {
    Measures m;
    exchange(n, n.comm, p, owner, Merge::Zbuffer, m);
    return m;
  };
  return s;
}

} // namespace zc::compositing
