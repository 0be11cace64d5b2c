#pragma once
// The messages addressed to one rank and not yet received. Messages of one (source, tag) are taken
// in the order they were sent, each no earlier than its arrival (so a message never overtakes an
// earlier one of its source and tag). A receive from any source takes, among the sources' oldest
// messages with that tag, the one that arrived first (the lower source rank on a tie): the order in
// which a real node's buffer would have filled.
//
// Kept per source, in send order: a node rarely has more than a few messages of one source
// pending, so a short scan beats any index. A source's oldest message has a place of its own, so
// that hearing from many sources one message at a time (an all-to-all) allocates nothing.
// Any-source receives scan only the sources with something pending.
#include <cstdint>
#include <memory>
#include <vector>

#include "sim/transit.hpp"

namespace zc {

class Inbox {
public:
  explicit Inbox(int sources = 0) : by_source_(std::size_t(sources)) {}

  // In the order of sending (arrival may be kNotYet and be set later).
  void push(TransitPtr m);
  // The message recv(src, tag) takes at time `now` (src may be kAnySource), or null; then `wake`
  // is the earliest arrival that could change the answer (kNotYet if none is known).
  TransitPtr take(int src, int tag, double now, double& wake);

private:
  // One source's pending messages in send order: the oldest, then the others, and the source's
  // place in pending_sources_ (24 bytes when there are none: an inbox has one a rank; a push or a
  // take reads one cache line of it).
  struct Queue {
    TransitPtr first;
    std::unique_ptr<std::vector<TransitPtr>> rest; // made when a second one is pending
    int slot = -1;                                 // index in pending_sources_, or -1
    Queue() = default;
    Queue(const Queue& o)
        : first(o.first),
          rest(o.rest ? std::make_unique<std::vector<TransitPtr>>(*o.rest) : nullptr),
          slot(o.slot) {}
    Queue(Queue&&) noexcept = default;
    bool empty() const { return !first; }
    std::size_t size() const { return first ? 1 + (rest ? rest->size() : 0) : 0; }
    const TransitPtr& operator[](std::size_t i) const { return i == 0 ? first : (*rest)[i - 1]; }
    void push(TransitPtr m);
    TransitPtr remove(std::size_t i);
  };
  // The oldest pending message of (src, tag), or -1.
  int oldest(int src, int tag) const;
  TransitPtr remove(int src, int index);

  std::vector<Queue> by_source_;     // source -> pending, in send order
  std::vector<int> pending_sources_; // sources whose list is not empty
};

} // namespace zc
