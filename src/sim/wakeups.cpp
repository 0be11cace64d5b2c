#include "sim/wakeups.hpp"

#include <algorithm>
#include <cmath>

#include <simgrid/kernel/Timer.hpp>
#include <simgrid/s4u.hpp>

namespace zc {

namespace sg = simgrid::s4u;
using simgrid::kernel::timer::Timer;

namespace {
constexpr double kNoWakeup = std::numeric_limits<double>::quiet_NaN();

// Stably by order (the rule for parties resumed at one date). A date usually resumes a handful of
// parties: an insertion sort then, instead of stable_sort's buffer for each date.
void sort_by_order(std::vector<Wakeups::Sleeper*>& v) {
  const auto before = [](const Wakeups::Sleeper* a, const Wakeups::Sleeper* b) {
    return a->order < b->order;
  };
  if (v.size() > 32) {
    std::stable_sort(v.begin(), v.end(), before);
    return;
  }
  for (std::size_t i = 1; i < v.size(); ++i) {
    Wakeups::Sleeper* s = v[i];
    std::size_t j = i;
    for (; j > 0 && before(s, v[j - 1]); --j)
      v[j] = v[j - 1];
    v[j] = s;
  }
}

// The Wakeups of the simulation this thread runs, whose clock SimGrid's time advances update.
thread_local Wakeups* clock_owner = nullptr;
} // namespace

Wakeups::Wakeups(double precision, SimCost& cost)
    : precision_(precision), cost_(cost), now_(sg::Engine::get_clock()) {
  static thread_local bool connected = false;
  if (!connected) {
    sg::Engine::on_time_advance_cb([](double) {
      if (!clock_owner) return;
      clock_owner->now_ = sg::Engine::get_clock();
      ++clock_owner->cost_.time_steps;
    });
    connected = true;
  }
  clock_owner = this;
}

Wakeups::~Wakeups() {
  cancel_all();
  if (clock_owner == this) clock_owner = nullptr;
}

void Wakeups::set_after(Sleeper& s, double seconds, double reached) {
  if (stopped_) return;
  unset(s);
  const double now = now_;
  const double date = seconds > 0 ? now + std::max(seconds, precision_) : now;
  s.date = date;
  s.reached = reached;
  auto [it, fresh] = due_.try_emplace(date);
  if (fresh) {
    it->second.timer = Timer::set(date, [this, date] { fire(date); });
    ++cost_.timers;
    if (!spare_.empty()) { // a list of a date gone, its capacity kept
      it->second.sleepers = std::move(spare_.back());
      spare_.pop_back();
    }
  }
  it->second.sleepers.push_back(&s); // fire() puts them in order
}

void Wakeups::set_until(Sleeper& s, double deadline) {
  set_after(s, deadline - now_, deadline);
}

void Wakeups::unset(Sleeper& s) {
  if (std::isnan(s.date)) return;
  auto it = due_.find(s.date);
  s.date = kNoWakeup;
  auto& v = it->second.sleepers;
  v.erase(std::find(v.begin(), v.end(), &s));
  if (v.empty()) {
    it->second.timer->remove();
    keep(std::move(v));
    due_.erase(it);
  }
}

double Wakeups::wait(Sleeper& s) {
  s.actor = sg::Actor::self();
  ++cost_.actor_switches;
  sg::this_actor::suspend();
  return s.reached;
}

// Runs in SimGrid's maestro, once the clock has reached `date` (SimGrid deletes this timer). The
// parties due within the precision after the clock resume now too, as SimGrid ends together the
// sleeps it cannot tell apart (their timers are dropped); all of them in their order.
void Wakeups::fire(double date) {
  std::vector<Sleeper*>& resumed = resumed_;
  resumed.clear();
  for (auto it = due_.begin(); it != due_.end() && it->first - now_ < precision_;) {
    if (it->first != date) it->second.timer->remove();
    for (Sleeper* s : it->second.sleepers) {
      s->date = kNoWakeup;
      resumed.push_back(s);
    }
    keep(std::move(it->second.sleepers));
    it = due_.erase(it);
  }
  sort_by_order(resumed);
  for (Sleeper* s : resumed)
    s->actor->resume();
}

void Wakeups::keep(std::vector<Sleeper*> list) {
  list.clear();
  if (list.capacity() != 0 && spare_.size() < 64) spare_.push_back(std::move(list));
}

void Wakeups::cancel_all() {
  stopped_ = true;
  for (auto& [date, due] : due_) {
    due.timer->remove();
    for (Sleeper* s : due.sleepers)
      s->date = kNoWakeup;
  }
  due_.clear();
}

} // namespace zc
