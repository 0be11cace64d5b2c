#pragma once
// NodeContext of a real MPI process: work is counted, not charged (the hardware has spent the
// time), phases are measured wall-clock, memory is tracked against an optional limit.
#include "mpi/mpi_comm.hpp"
#include "sim/recording_context.hpp"

namespace zc {

class MpiContext final : public RecordingContext {
public:
  using RecordingContext::RecordingContext;
  // busy_s is measured as the time not spent in communication calls.
  NodeRecord record(nlohmann::json rank) const override {
    NodeRecord r = RecordingContext::record(std::move(rank));
    r.stats.busy_s = std::max(0.0, r.stats.finish_s - r.stats.comm_s);
    return r;
  }

protected:
  void spend(const Counters&) override {}
};

} // namespace zc
