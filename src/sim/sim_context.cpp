#include "sim/sim_context.hpp"

namespace zc {

void SimContext::spend(const Counters& w) {
  const double s = cost_.seconds(w) * (draw_ ? draw_->phase(current_phase()) : 1.0);
  if (s > 0) {
    const double t0 = delivery_.now();
    delivery_.compute(rank_, s);
    stats().busy_s += s;
    if (stats().log) stats().log->activity(Activity::Compute, t0, delivery_.now());
  }
}

} // namespace zc
