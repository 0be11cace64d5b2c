#include "sim/inbox.hpp"

namespace zc {

void Inbox::push(TransitPtr m) {
  auto& q = queues_[key(m->src, m->tag)];
  if (q.empty()) heads_[m->tag].insert({m->arrival, m->src});
  q.push_back(std::move(m));
}

void Inbox::arrived(const Transit& m) {
  auto it = queues_.find(key(m.src, m.tag));
  if (it == queues_.end() || it->second.front().get() != &m) return; // not at the head yet
  auto& h = heads_[m.tag];
  h.erase({kNotYet, m.src});
  h.insert({m.arrival, m.src});
}

TransitPtr Inbox::pop(std::deque<TransitPtr>& q, std::uint64_t k) {
  TransitPtr m = std::move(q.front());
  q.pop_front();
  auto& h = heads_[m->tag];
  h.erase({m->arrival, m->src});
  if (!q.empty())
    h.insert({q.front()->arrival, m->src});
  else
    queues_.erase(k);
  if (h.empty()) heads_.erase(m->tag);
  return m;
}

TransitPtr Inbox::take(int src, int tag, double now, double& wake) {
  wake = kNotYet;
  if (src == kAnySource) {
    auto h = heads_.find(tag);
    if (h == heads_.end()) return nullptr;
    const auto [arrival, first] = *h->second.begin();
    if (arrival > now) {
      wake = arrival;
      return nullptr;
    }
    src = first;
  }
  const std::uint64_t k = key(src, tag);
  auto it = queues_.find(k);
  if (it == queues_.end()) return nullptr;
  if (it->second.front()->arrival > now) {
    wake = it->second.front()->arrival;
    return nullptr;
  }
  return pop(it->second, k);
}

} // namespace zc
