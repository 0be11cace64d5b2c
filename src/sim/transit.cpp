#include "sim/transit.hpp"

namespace zc {

namespace {
// The Transits of this thread no one holds, freed with the thread.
struct FreeTransits {
  std::vector<Transit*> list;
  FreeTransits() = default;
  FreeTransits(const FreeTransits&) = delete;
  FreeTransits& operator=(const FreeTransits&) = delete;
  ~FreeTransits() {
    for (Transit* t : list)
      delete t;
  }
};
thread_local FreeTransits free_transits;
} // namespace

TransitPtr TransitPtr::make() {
  TransitPtr p;
  auto& list = free_transits.list;
  if (list.empty()) {
    p.t_ = new Transit{};
  } else {
    p.t_ = list.back();
    list.pop_back();
  }
  p.t_->owners = 1;
  return p;
}

void TransitPtr::recycle(Transit* t) {
  t->data = {};
  t->blocks.clear();
  t->bundle = false;
  t->charged = 0;
  t->sent_at = 0;
  t->arrival = kNotYet;
  t->stage = t->next_channel = 0;
  free_transits.list.push_back(t); // its holds stay, to be written over by the next message
}

} // namespace zc
