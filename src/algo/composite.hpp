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

// Composites p over every node of the machine by strategy s into the region owner; work counted
// into w (charged by the caller when its phase ends).
inline compositing::Measures composite(NodeContext& ctx, const compositing::Strategy& s,
                                       compositing::Picture& p, const std::vector<int>& owner,
                                       Counters& w) {
  ContextMemory memory(ctx);
  compositing::Node node{ctx.comm(), memory, w};
  return s.composite(node, p, owner);
}

// Kurc et al.'s records (records.hpp): a WPA entry, a z-buffer location, a scanline count.
inline compositing::PixelRecords kurc_pixel_records() {
  return {records::kurc::kWinningPixel, records::kurc::kZbufferLocation,
          records::kurc::kCountEntry};
}

} // namespace zc
