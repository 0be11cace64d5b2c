#pragma once
// The bookkeeping every backend's NodeContext shares: operations counted per phase, phase times on
// the backend's clock (Comm::now), node memory against a capacity, the pictures handed over, the
// algorithm's metrics; record() turns them into the report's NodeRecord. A backend derives and
// says what charging work costs (spend): the simulator sleeps for the modelled time, a real
// machine has already spent it.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "algo/algorithm.hpp"
#include "run/report.hpp"

namespace zc {

class RecordingContext : public NodeContext {
public:
  // `facts`: scene_facts(scene) when the caller has worked them out for several contexts (the
  // simulator's nodes share one scene); null to work them out on first use.
  RecordingContext(Comm& comm, NodeStats& stats, const Scene& scene, const AlgorithmOptions& opt,
                   double memory_capacity, std::vector<FrameImage>& images,
                   const SceneFacts* facts = nullptr)
      : comm_(comm), stats_(stats), scene_(scene), opt_(opt), memory_capacity_(memory_capacity),
        images_(images), facts_(facts) {}

  Comm& comm() override { return comm_; }
  const Scene& scene() const override { return scene_; }
  const SceneFacts& scene_facts() const override;
  const AlgorithmOptions& options() const override { return opt_; }
  void charge(const Counters& work) final;
  void phase_begin(const std::string& name) final;
  void phase_end() final;
  void start_timed_region() final;
  void end_timed_region() final;
  void alloc(double bytes, const std::string& what) final;
  void release(double bytes) final;
  void deliver_image(int frame, Framebuffer image) final;
  void deliver_rows(int frame, Framebuffer rows) final;
  nlohmann::json& metrics() final { return metrics_; }

  // What this node recorded, for the report. Operations charged inside each phase are kept per
  // phase (the innermost open one; "" outside every phase): with the phase durations, the linear
  // model the calibration fits (time = counts x costs + waiting).
  virtual NodeRecord record(Recorder who) const;

protected:
  // The cost of charged work on this backend.
  virtual void spend(const Counters& work) = 0;
  // The innermost open phase ("" outside every phase).
  const std::string& current_phase() const {
    static const std::string none;
    return open_.empty() ? none : open_.back().first;
  }
  NodeStats& stats() const { return stats_; }

private:
  Comm& comm_;
  NodeStats& stats_;
  const Scene& scene_;
  const AlgorithmOptions& opt_;
  double memory_capacity_;
  std::vector<FrameImage>& images_;
  const SceneFacts* facts_;
  mutable std::optional<SceneFacts> own_facts_; // when none were given
  Counters work_;
  std::vector<std::pair<std::string, double>> open_;
  std::map<std::string, double> phase_totals_;
  std::map<std::string, Counters> phase_work_;
  std::vector<std::string> phase_order_;
  nlohmann::json metrics_ = nlohmann::json::object();
};

} // namespace zc
