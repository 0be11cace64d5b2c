#pragma once
// NodeContext of a real MPI process: work is counted, not charged (the hardware has spent the
// time), phases are measured wall-clock, memory is tracked against an optional limit.
#include "mpi/mpi_comm.hpp"
#include "run/recording_context.hpp"

namespace zc {

class MpiContext final : public RecordingContext {
public:
  using RecordingContext::RecordingContext;
  // busy_s is measured as the time not spent in communication calls.
  NodeRecord record(Recorder who) const override {
    NodeRecord r = RecordingContext::record(who);
    r.stats.busy_s = std::max(0.0, r.stats.finish_s - r.stats.comm_s);
    if (r.stats.log) r.stats.log = with_compute(*r.stats.log, r.stats.finish_s);
    return r;
  }

protected:
  void spend(const Counters&) override {}

private:
  // The measured timeline: the time outside communication calls, up to the finish, is compute.
  static std::shared_ptr<EventLog> with_compute(const EventLog& log, double finish_s) {
    auto out = std::make_shared<EventLog>(log);
    out->activities.clear();
    double t = 0;
    for (const auto& a : log.activities) {
      out->activity(Activity::Compute, t, a.begin_s);
      out->activity(a.kind, a.begin_s, a.end_s);
      t = a.end_s;
    }
    out->activity(Activity::Compute, t, finish_s);
    return out;
  }
};

} // namespace zc
