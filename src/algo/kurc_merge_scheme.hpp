#pragma once
// Kurc, Aykanat, Ozguc: one pixel merging scheme per file behind this interface (as IceT keeps one
// compositing strategy per file behind one strategy call). A scheme decides how a node keeps its
// local pixels (the local z-buffer, §2 second step) and how the nodes exchange and merge them so
// that each ends with the final pixels of its share of the screen (pixel merging, §3):
//   ZBUF-EXC  full z-buffers, every location exchanged by recursive halving  kurc_zbuf_exc.cpp
//   PAIR      active pixels, d pairwise exchanges (§3.1)                     kurc_pair.cpp
//   AAPC      active pixels, all-to-all personalised (§3.2)                  kurc_aapc.cpp
// PAIR and AAPC share the modified scanline z-buffer and the screen partition by active pixel
// counts (§4: RS, HBP or even; kurc_partition*.cpp) in kurc_active_merging.cpp.
#include <cstdint>
#include <memory>
#include <vector>

#include "algo/algorithm.hpp"
#include "algo/kurc_partition.hpp"
#include "algo/kurc_span_lists.hpp"
#include "algo/records.hpp"
#include "raster/active_pixels.hpp"
#include "raster/renderer.hpp"

namespace zc::kurc {

// What pixel merging measured on a node: bytes it sent at each communication step (Fig. 1) and
// its merge operations (Fig. 2).
struct MergeMeasures {
  std::vector<double> step_bytes;
  std::uint64_t merge_load = 0;
};

class MergeScheme {
public:
  virtual ~MergeScheme() = default;
  // The scheme's name in reports: "zbuf-exc", "pair" or "aapc".
  virtual const char* name() const = 0;
  // Local z-buffer (§2, second step) of the node's span lists; work counted into w.
  virtual void local_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans,
                             Counters& w) = 0;
  // Pixel merging (§3); work counted into w, charged by the caller when the phase ends.
  virtual MergeMeasures merge(NodeContext& ctx, Counters& w) = 0;
  // The final pixels the node holds after merging (taken once, for the output); the work of
  // making them records is counted into w.
  virtual ActivePixels final_pixels(Counters& w) = 0;
};

std::unique_ptr<MergeScheme> make_zbuf_exc();
std::unique_ptr<MergeScheme> make_pair(const ScreenPartition& partition);
std::unique_ptr<MergeScheme> make_aapc(const ScreenPartition& partition);

// A sparse pixel message (serialize_sparse) as the paper's program sends it: its row counts, and
// each pixel as a WPA entry (records.hpp) instead of zcube's kWirePixelBytes.
Message sparse_message(Bytes payload);
// The WPA (or merged pixels) as the paper's node holds it: a WPA entry a pixel and the scanline
// offsets (a C int each).
inline double wpa_record_bytes(const ActivePixels& a) {
  return double(a.count() * records::kurc::kWinningPixel +
                a.row_begin.size() * records::kurc::kCountEntry);
}

// Message tags of the schemes' exchanges (stage i uses base + i).
constexpr int kTagPair = 100, kTagZbuf = 200;

} // namespace zc::kurc
