#pragma once
// NodeContext of a simulated node: charged work advances the virtual clock by counts x costs.
#include "machine/machine.hpp"
#include "machine/uncertainty.hpp"
#include "run/recording_context.hpp"
#include "sim/sim_comm.hpp"

namespace zc {

class SimContext final : public RecordingContext {
public:
  SimContext(SimComm& comm, NodeStats& stats, const Scene& scene, const SceneFacts& facts,
             const AlgorithmOptions& opt, CostTable cost, double memory_bytes,
             std::vector<FrameImage>& images, const ModelDraw* draw = nullptr)
      : RecordingContext(comm, stats, scene, opt, memory_bytes, images, &facts), cost_(cost),
        delivery_(comm.delivery()), rank_(comm.rank()), draw_(draw) {}

protected:
  void spend(const Counters& work) override;

private:
  CostTable cost_;
  Delivery& delivery_;
  int rank_;
  const ModelDraw* draw_; // its structural factor per phase, when one is priced
};

} // namespace zc
