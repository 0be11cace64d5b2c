#pragma once
// A node program's way into the compositing layer (src/compositing): the node's memory and
// counted work handed to a strategy, and the records the program's paper charges.
#include "algo/algorithm.hpp"
#include "algo/records.hpp"
#include "compositing/records.hpp"
#include "compositing/strategy.hpp"

namespace zc {

// NodeContext's modelled memory as the compositing layer sees it.
class ContextMemory : public compositing::Memory {
public:
  explicit ContextMemory(NodeContext& ctx) : ctx_(ctx) {}
  void alloc(double bytes, const std::string& what) override { ctx_.alloc(bytes, what); }
  void release(double bytes) override { ctx_.release(bytes); }

private:
  NodeContext& ctx_;
};

// How a program charges the merge work of a multi-round strategy.
enum class MergeCharge {
  AtPhaseEnd, // counted into w, charged by the caller when its phase ends (Kurc et al.'s programs,
              // as the calibration fitted them: a node's merge does not delay its next send)
  ByRound     // charged after each round's merge, before the node sends the merged rows on
};

// Composites p over every node of the machine by strategy s into the region owner; work counted
// into w (what is left of it charged by the caller when its phase ends).
inline compositing::Measures composite(NodeContext& ctx, const compositing::Strategy& s,
                                       compositing::Picture& p, const std::vector<int>& owner,
                                       Counters& w, MergeCharge how = MergeCharge::AtPhaseEnd) {
  ContextMemory memory(ctx);
  compositing::Node node{ctx.comm(), memory, w};
  if (how == MergeCharge::ByRound) node.charge_round = [&ctx](const Counters& k) { ctx.charge(k); };
  return s.composite(node, p, owner);
}

// Kurc et al.'s records (records.hpp): a WPA entry, a z-buffer location, a scanline count.
inline compositing::PixelRecords kurc_pixel_records() {
  return {records::kurc::kWinningPixel, records::kurc::kZbufferLocation,
          records::kurc::kCountEntry};
}

} // namespace zc
