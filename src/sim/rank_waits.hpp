#pragma once
// Where the simulated parties wait (Delivery and the network models): one Waiter a rank, and one
// for the network's actor, each suspended and resumed through Wakeups, with what it waits for, so
// that an arrival wakes only a party that wants it.
#include <limits>
#include <vector>

#include "sim/transit.hpp"
#include "sim/wakeups.hpp"

namespace zc {

// Before any date: a wait's "nothing reached yet".
constexpr double kNever = -std::numeric_limits<double>::infinity();

struct Waiter {
  Wakeups::Sleeper sleeper;
  bool blocked = false, receiving = false;
  int src = 0, tag = 0;
  const Transit* send = nullptr;
  double deadline = kNotYet;
};

class RankWaits {
public:
  // `parties` waiters, resumed in their index order at one date: the ranks, then the network's.
  RankWaits(Wakeups& wakeups, int parties);

  Waiter& operator[](int i) { return waiters_[std::size_t(i)]; }
  Waiter& network() { return waiters_.back(); }

  // Both return the deadline reached and set `now` to the time they return at.
  double block(Waiter& w, double deadline, double& now);
  double sleep_until(Waiter& w, double deadline, double& now);
  // The waiter woken at m's arrival if it waits for m (a sender) or for a message like m.
  void notify(Waiter& w, const Transit& m);
  // A blocked waiter's wake-up moved to `t`, earlier than its deadline.
  void wake(Waiter& w, double t);
  // m's arrival is dated: its destination and its sender told.
  void arrived(Transit& m) {
    notify(waiters_[std::size_t(m.dst)], m);
    notify(waiters_[std::size_t(m.src)], m);
  }

private:
  Wakeups& wakeups_;
  std::vector<Waiter> waiters_;
};

} // namespace zc
