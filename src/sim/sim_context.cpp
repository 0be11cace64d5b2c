#include "sim/sim_context.hpp"

#include <simgrid/s4u.hpp>

namespace zc {

void SimContext::spend(const Counters& w) {
  const double s = cost_.seconds(w);
  if (s > 0) {
    simgrid::s4u::this_actor::sleep_for(s);
    stats().busy_s += s;
  }
}

} // namespace zc
