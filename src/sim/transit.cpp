#include "sim/transit.hpp"

#include <memory>

#include "sim/free_list.hpp"

namespace zc {

namespace {
// The Transits of this thread no one holds.
thread_local FreeList<Transit, std::default_delete<Transit>> free_transits;
} // namespace

TransitPtr TransitPtr::make() {
  TransitPtr p;
  p.t_ = free_transits.take();
  if (!p.t_) p.t_ = new Transit{};
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
  free_transits.give(t); // its holds stay, to be written over by the next message
}

} // namespace zc
