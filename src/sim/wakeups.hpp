#pragma once
// Where ranks wait in virtual time. A waiting rank's actor is suspended in SimGrid and resumed by
// zcube at a date: the one SimGrid's own timed wait would have ended at (the clock when the wait
// was set plus its duration, never less than SimGrid's precision), so that the clock reads as it
// did with SimGrid's sleeps. A SimGrid timer per distinct date resumes the parties due at it, with
// those due within the precision after it (SimGrid ends such sleeps together too), in their order
// (rank order; the rule for ranks resumed at one virtual time, docs/simulator.md).
// No SimGrid activity is made per wait: a sleep or a semaphore's timed wait
// costs a CPU action and a variable of its bandwidth-sharing system each.
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

#include <simgrid/forward.h>

#include "run/sim_cost.hpp"

namespace zc {

class Wakeups {
public:
  // One waiting party (a rank, or the network's actor).
  struct Sleeper {
    int order = 0;                        // resumed before those of higher order at one date
    simgrid::s4u::Actor* actor = nullptr; // set by wait()
    double date = std::numeric_limits<double>::quiet_NaN(); // its pending wake-up, NaN if none
    double reached = 0; // what the caller learns on waking: the deadline of the wake-up
  };

  // `precision`: SimGrid's timing precision (surf/precision), the shortest timed wait. `cost`
  // counts SimGrid's time steps, the timers set and the waits (SimCost), and must outlive this.
  Wakeups(double precision, SimCost& cost);
  Wakeups(const Wakeups&) = delete;
  Wakeups& operator=(const Wakeups&) = delete;
  ~Wakeups();

  // Sets (or moves) s's wake-up to the end of a wait of `seconds` from now, as SimGrid dates a
  // sleep: now + max(seconds, precision), now itself when seconds <= 0. On waking, s learns
  // `reached`.
  void set_after(Sleeper& s, double seconds, double reached);
  // The same for a wait until `deadline` (a sleep of deadline - now), which s learns on waking.
  void set_until(Sleeper& s, double deadline);
  // Suspends the calling actor until its wake-up (none set: until one is set and comes). Returns
  // the deadline of the wake-up that resumed it.
  double wait(Sleeper& s);
  // SimGrid's clock, kept up to date by SimGrid's signal of time advances (cheaper than asking
  // SimGrid at every message).
  double now() const { return now_; }
  // Drops every pending wake-up (a finished or failed run: no timer may move the clock further).
  void cancel_all();

private:
  struct Due {
    simgrid::kernel::timer::Timer* timer = nullptr;
    std::vector<Sleeper*> sleepers; // in the order their wake-ups were set
  };
  void unset(Sleeper& s);
  void fire(double date);
  // Keeps the list of a date gone (emptied, its capacity kept) for the next new date.
  void keep(std::vector<Sleeper*> list);

  double precision_;
  SimCost& cost_;
  double now_;
  bool stopped_ = false; // after cancel_all(): no wake-up is set any more
  std::map<double, Due> due_;
  std::vector<Sleeper*> resumed_;            // fire()'s scratch
  std::vector<std::vector<Sleeper*>> spare_; // lists of dates gone: no allocation per new date
};

} // namespace zc
