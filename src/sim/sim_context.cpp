#include "sim/sim_context.hpp"

#include <simgrid/s4u.hpp>

namespace zc {

void SimContext::spend(const Counters& w) {
  const double s = cost_.seconds(w);
  if (s > 0) {
    const double t0 = simgrid::s4u::Engine::get_clock();
    simgrid::s4u::this_actor::sleep_for(s);
    stats().busy_s += s;
    if (stats().log)
      stats().log->activity(Activity::Compute, t0, simgrid::s4u::Engine::get_clock());
  }
}

} // namespace zc
