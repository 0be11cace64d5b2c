#pragma once
// NodeContext of a simulated node: charges CPU work to the virtual clock, records phases, models
// node memory.
#include <map>
#include <string>
#include <vector>

#include "algo/algorithm.hpp"
#include "machine/machine.hpp"
#include "sim/sim_comm.hpp"

namespace zc {

class SimContext final : public NodeContext {
public:
  SimContext(SimComm& comm, NodeStats& stats, const Scene& scene, const AlgorithmOptions& opt,
             CostTable cost, double memory_bytes, std::vector<FrameImage>& images)
      : comm_(comm), stats_(stats), scene_(scene), opt_(opt), cost_(cost),
        memory_capacity_(memory_bytes), images_(images) {}

  Comm& comm() override { return comm_; }
  const Scene& scene() const override { return scene_; }
  const AlgorithmOptions& options() const override { return opt_; }
  void charge(const Counters& work) override;
  void phase_begin(const std::string& name) override;
  void phase_end() override;
  void alloc(double bytes, const std::string& what) override;
  void release(double bytes) override;
  void deliver_image(int frame, Framebuffer image) override;
  void deliver_rows(int frame, Framebuffer rows) override;
  nlohmann::json& metrics() override { return metrics_; }

  const Counters& work() const { return work_; }
  // What this node recorded, for the report.
  NodeRecord record(nlohmann::json rank) const;
  const std::map<std::string, double>& phase_totals() const { return phase_totals_; }
  const std::vector<std::string>& phase_order() const { return phase_order_; }
  // Operations charged inside each phase (the innermost open one; "" outside every phase): with the
  // phase durations, the linear model the calibration fits (time = counts x costs + waiting).
  const std::map<std::string, Counters>& phase_work() const { return phase_work_; }

private:
  SimComm& comm_;
  NodeStats& stats_;
  const Scene& scene_;
  const AlgorithmOptions& opt_;
  CostTable cost_;
  double memory_capacity_;
  std::vector<FrameImage>& images_;
  Counters work_;
  std::vector<std::pair<std::string, double>> open_;
  std::map<std::string, double> phase_totals_;
  std::map<std::string, Counters> phase_work_;
  std::vector<std::string> phase_order_;
  nlohmann::json metrics_ = nlohmann::json::object();
};

} // namespace zc
