#include "sim/rank_waits.hpp"

#include "comm/comm.hpp"

namespace zc {

RankWaits::RankWaits(Wakeups& wakeups, int parties)
    : wakeups_(wakeups), waiters_(std::size_t(parties)) {
  for (int i = 0; i < parties; ++i)
    waiters_[std::size_t(i)].sleeper.order = i; // ranks, then the network's actor
}

// A rank blocks until its wake-up: its deadline, or an earlier one that a message moved it to
// (notify). Nobody else can run between the decision to block and the block itself (actors take
// turns on one thread, and a rank yields only in Wakeups::wait).
double RankWaits::block(Waiter& w, double deadline, double& now) {
  w.blocked = true;
  w.deadline = deadline;
  if (deadline != kNotYet) wakeups_.set_until(w.sleeper, deadline);
  const double reached = wakeups_.wait(w.sleeper);
  w.blocked = false;
  now = wakeups_.now();
  return reached;
}

void RankWaits::notify(Waiter& w, const Transit& m) {
  if (!w.blocked || !(m.arrival < w.deadline)) return;
  const bool wanted =
      w.send == &m || (w.receiving && w.tag == m.tag && (w.src == kAnySource || w.src == m.src));
  if (wanted) wake(w, m.arrival);
}

// The waiter wakes when the message it wants has arrived, at the date a wait set now for that
// arrival would end at (as when it was woken now and then slept until the arrival). It stays
// blocked: a message arriving earlier still moves its wake-up.
void RankWaits::wake(Waiter& w, double t) {
  w.deadline = t;
  wakeups_.set_until(w.sleeper, t);
}

// A known arrival that nothing can bring forward is waited for without being marked blocked
// (nobody needs to move this rank's wake-up). As with block(), the deadline itself counts as
// reached.
double RankWaits::sleep_until(Waiter& w, double deadline, double& now) {
  if (deadline - now > 0) {
    wakeups_.set_until(w.sleeper, deadline);
    wakeups_.wait(w.sleeper);
    now = wakeups_.now();
  }
  return deadline;
}

} // namespace zc
