#pragma once
// The messages addressed to one rank and not yet received, indexed by (source, tag). Messages of
// one (source, tag) are taken in the order they were sent, each no earlier than its arrival (so a
// message never overtakes an earlier one of its source and tag). A receive from any source takes,
// among the sources' oldest messages with that tag, the one that arrived first (the lower source
// rank on a tie): the order in which a real node's buffer would have filled.
#include <cstdint>
#include <deque>
#include <set>
#include <unordered_map>

#include "sim/transit.hpp"

namespace zc {

class Inbox {
public:
  // In the order of sending (arrival may be kNotYet and be set later through arrived()).
  void push(TransitPtr m);
  // m's arrival time, kNotYet until now, has been set.
  void arrived(const Transit& m);
  // The message recv(src, tag) takes at time `now` (src may be kAnySource), or null; then `wake`
  // is the earliest arrival that could change the answer (kNotYet if none is known).
  TransitPtr take(int src, int tag, double now, double& wake);

private:
  static std::uint64_t key(int src, int tag) {
    return std::uint64_t(std::uint32_t(src)) << 32 | std::uint32_t(tag);
  }
  TransitPtr pop(std::deque<TransitPtr>& q, std::uint64_t k);

  std::unordered_map<std::uint64_t, std::deque<TransitPtr>> queues_; // (src, tag) -> in send order
  std::unordered_map<int, std::set<std::pair<double, int>>> heads_;  // tag -> {(arrival, src)}
};

} // namespace zc
