#pragma once
// Kurc, Aykanat, Ozguc: a pixel merging scheme is a local z-buffer (§2 second step) and a
// compositing strategy of src/compositing over a share of the screen (§3, §4):
//   ZBUF-EXC  full z-buffer (dense picture), binary swap over the even halving   kurc_zbuf_exc.cpp
//   PAIR      winning pixel array, binary swap (§3.1) over an RS/HBP/even share
//   AAPC      winning pixel array, direct send (§3.2) over an RS/HBP/even share
// The share (§4.1, §4.2) is made from the machine-wide active pixel counts per scanline
// (kurc_partition*.cpp); the even halving reads no counts.
#include <cstdint>
#include <memory>
#include <vector>

#include "algo/algorithm.hpp"
#include "algo/kurc/kurc_partition.hpp"
#include "algo/kurc/kurc_span_lists.hpp"
#include "compositing/strategy.hpp"
#include "raster/active_pixels.hpp"
#include "raster/renderer.hpp"

namespace zc::kurc {

using MergeMeasures = compositing::Measures;

class MergeScheme {
public:
  // partition nullptr: a full z-buffer over the even halving (ZBUF-EXC); else active pixels.
  MergeScheme(const char* name, compositing::Strategy strategy, const ScreenPartition* partition)
      : name_(name), strategy_(std::move(strategy)), partition_(partition) {}
  // The scheme's name in reports: "zbuf-exc", "pair" or "aapc".
  const char* name() const { return name_; }
  // Local z-buffer (§2, second step) of the node's span lists; work counted into w.
  void local_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans, Counters& w);
  // Pixel merging (§3); work counted into w, charged by the caller when the phase ends.
  MergeMeasures merge(NodeContext& ctx, Counters& w);
  // The final pixels the node holds after merging (taken once, for the output); the work of
  // making them records is counted into w.
  ActivePixels final_pixels(Counters& w) { return picture_->final_pixels(w); }

private:
  std::vector<int> share_scanlines(NodeContext& ctx, Counters& w) const;

  const char* name_;
  compositing::Strategy strategy_;
  const ScreenPartition* partition_;
  std::unique_ptr<compositing::Picture> picture_;
  std::vector<std::int32_t> row_pixels_; // the local active pixels of each scanline
  int height_ = 0;
};

std::unique_ptr<MergeScheme> make_zbuf_exc();
std::unique_ptr<MergeScheme> make_pair(const ScreenPartition& partition);
std::unique_ptr<MergeScheme> make_aapc(const ScreenPartition& partition);

// ZBUF-EXC's local z-buffer: the span lists z-buffered into a full-screen frame buffer
// (kurc_zbuf_exc.cpp).
Framebuffer full_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans,
                         Counters& w);

} // namespace zc::kurc
