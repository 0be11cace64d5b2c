#include "sim/inbox.hpp"

#include <stdexcept>

namespace zc {

void Inbox::Queue::push(TransitPtr m) {
  if (!first) {
    first = std::move(m);
    return;
  }
  if (!rest) rest = std::make_unique<std::vector<TransitPtr>>();
  rest->push_back(std::move(m));
}

TransitPtr Inbox::Queue::remove(std::size_t i) {
  TransitPtr m;
  if (i == 0) {
    m = std::move(first);
    if (rest && !rest->empty()) {
      first = std::move(rest->front());
      rest->erase(rest->begin());
    }
  } else {
    m = std::move((*rest)[i - 1]);
    rest->erase(rest->begin() + std::ptrdiff_t(i - 1));
  }
  return m;
}

void Inbox::push(TransitPtr m) {
  const int s = m->src;
  if (s < 0 || std::size_t(s) >= by_source_.size())
    throw std::out_of_range("inbox: source rank " + std::to_string(s));
  auto& q = by_source_[std::size_t(s)];
  if (q.empty()) {
    q.slot = int(pending_sources_.size());
    pending_sources_.push_back(s);
  }
  q.push(std::move(m));
}

int Inbox::oldest(int src, int tag) const {
  const auto& q = by_source_[std::size_t(src)];
  for (std::size_t i = 0; i < q.size(); ++i)
    if (q[i]->tag == tag) return int(i);
  return -1;
}

TransitPtr Inbox::remove(int src, int index) {
  auto& q = by_source_[std::size_t(src)];
  TransitPtr m = q.remove(std::size_t(index));
  if (q.empty()) { // swap-remove the source from the pending list
    const int at = q.slot;
    const int last = pending_sources_.back();
    pending_sources_[std::size_t(at)] = last;
    by_source_[std::size_t(last)].slot = at;
    pending_sources_.pop_back();
    q.slot = -1;
  }
  return m;
}

TransitPtr Inbox::take(int src, int tag, double now, double& wake) {
  wake = kNotYet;
  if (src == kAnySource) {
    // The earliest-arrived among the sources' oldest messages with this tag (lower source on a
    // tie); a head whose arrival is still unknown cannot be taken and dates nothing.
    int best = -1, best_index = -1;
    double best_arrival = kNotYet;
    for (int s : pending_sources_) {
      const int i = oldest(s, tag);
      if (i < 0) continue;
      const double a = by_source_[std::size_t(s)][std::size_t(i)]->arrival;
      if (best < 0 || a < best_arrival || (a == best_arrival && s < best)) {
        best = s;
        best_index = i;
        best_arrival = a;
      }
    }
    if (best < 0) return nullptr;
    if (best_arrival > now) {
      wake = best_arrival;
      return nullptr;
    }
    return remove(best, best_index);
  }
  const int i = oldest(src, tag);
  if (i < 0) return nullptr;
  const double a = by_source_[std::size_t(src)][std::size_t(i)]->arrival;
  if (a > now) {
    wake = a;
    return nullptr;
  }
  return remove(src, i);
}

} // namespace zc
