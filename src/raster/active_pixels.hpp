#pragma once
// Kurc, Aykanat, Ozguc §2: the modified scanline z-buffer. Spans go into per-scanline lists
// sorted by x_min (span list creation); then, scanline by scanline, spans are z-buffered through
// the Modified Scanline Array (MSA, one entry per column holding an index into the WPA) into the
// Winning Pixel Array (WPA), which keeps only the local foremost pixels, consecutively and in
// increasing x within each scanline. Because spans arrive sorted by x_min, a span splits into a
// first segment that overlaps pixels already produced on this scanline (depth comparisons) and a
// second segment of new pixels appended without comparison; the MSA is never re-initialised
// (entries below the scanline's "range" belong to earlier scanlines and are simply ignored).
#include <cstdint>
#include <vector>

#include "raster/framebuffer.hpp"
#include "raster/setup.hpp"
#include "raster/shade.hpp"
#include "util/counters.hpp"

namespace zc {

// One winning pixel: its column, depth, triangle id (the tie-break) and colour. On the wire it
// takes kWirePixelBytes (x 2, rgb 3, z 4, id 4).
struct WinningPixel {
  float z;
  std::uint32_t id;
  std::uint16_t x;
  std::uint8_t rgb[3];
};
constexpr std::size_t kWirePixelBytes = 13;

// A span record of the scanline span lists: its extent and the triangle that shades it.
struct SpanRecord {
  std::int32_t x0, x1;
  std::uint32_t tri; // index into the TriangleBatch
};

// Scanline span lists: spans of every local triangle, bucketed by scanline, each bucket sorted by
// increasing x_min (ties: increasing triangle id, then creation order), as §2 prescribes.
struct SpanLists {
  int height = 0;
  std::vector<std::uint32_t> row_begin; // height+1 offsets into spans
  std::vector<SpanRecord> spans;
  // Columns covered by some span, summed over the scanlines: the WPA's pixel count, so that
  // zbuffer_spans reserves its array once (grown by doubling, it was copied about once over: 12 %
  // of pair-rs's local z-buffer at 5120x5120, memory traffic no modelled program has).
  std::size_t covered = 0;
  std::size_t bytes() const { return spans.size() * sizeof(SpanRecord) + row_begin.size() * 4; }
};

SpanLists build_span_lists(const TriangleBatch& batch, int width, int height, Counters& c);

// The local foremost pixels of a set of scanlines: rows [y0, y1), each row's pixels consecutive
// and sorted by x.
struct ActivePixels {
  int width = 0;
  int y0 = 0, y1 = 0;
  std::vector<std::uint32_t> row_begin; // (y1-y0)+1 offsets into pixels
  std::vector<WinningPixel> pixels;

  std::size_t count() const { return pixels.size(); }
  std::uint32_t row_count(int y) const { return row_begin[y - y0 + 1] - row_begin[y - y0]; }
  std::size_t bytes() const { return pixels.size() * sizeof(WinningPixel) + row_begin.size() * 4; }
};

// The modified scanline z-buffer over all rows of the span lists; `msa` scratch is width entries.
// Counts c.wpa_tested for a first-segment fragment (its depth test through the MSA) and
// c.wpa_appended for a second-segment one (appended without comparison); pixels_generated and
// pixels_written as the frame-buffer loops count them.
ActivePixels zbuffer_spans(const SpanLists& lists, const TriangleBatch& batch,
                           const ShadeContext& ctx, int width, Counters& c);

// Merges two pixel sets over the same rows: per row a merge of two x-sorted lists, the nearer
// pixel (depth, then lower id) winning at equal x. Every pixel of either set is visited once (a
// comparison or a copy into the result): |retained| + |received| list merge steps
// (c.list_merges), Kurc et al.'s merge operations (Fig. 2), priced apart from a z-buffer merge's
// location compare (c.merge_ops): a different loop (docs/machines.md, "One cost per loop").
ActivePixels merge_active(const ActivePixels& retained, const ActivePixels& received, Counters& c);

// The rows of `a` for which keep(y) holds (the others emptied), over the same row range.
template <class Keep> ActivePixels select_rows(const ActivePixels& a, Keep keep) {
  ActivePixels r;
  r.width = a.width;
  r.y0 = a.y0;
  r.y1 = a.y1;
  r.row_begin.assign(a.row_begin.size(), 0);
  for (int y = a.y0; y < a.y1; ++y) {
    if (keep(y))
      r.pixels.insert(r.pixels.end(), a.pixels.begin() + a.row_begin[y - a.y0],
                      a.pixels.begin() + a.row_begin[y - a.y0 + 1]);
    r.row_begin[y - a.y0 + 1] = std::uint32_t(r.pixels.size());
  }
  return r;
}

// Compact wire format for sparse row sets: only non-empty rows travel, as (row, count) pairs.
std::vector<std::uint8_t> serialize_sparse(const ActivePixels& a);
// Reads a sparse message into a pixel set over rows [y0, y1).
ActivePixels deserialize_sparse(const std::uint8_t* data, std::size_t size, int width, int y0,
                                int y1);

// serialize_sparse(select_rows(a, owner[y] == k)) for every k in [0, parts), in one pass over the
// rows: an all-to-all's messages without a scan of every row per destination.
std::vector<std::vector<std::uint8_t>>
serialize_sparse_by_owner(const ActivePixels& a, const std::vector<int>& owner, int parts);

// The pixel set that deserializing each sparse message over rows [y0, y1) and merging them one
// after the other with merge_active (messages[0] first) gives, in time proportional to their rows
// and pixels instead of messages x (y1 - y0). pixel_counts[i] is messages[i]'s pixel count.
ActivePixels merge_sparse(const std::vector<const std::vector<std::uint8_t>*>& messages, int width,
                          int y0, int y1, std::vector<std::uint64_t>& pixel_counts);

// merge_active(a, deserialize_sparse(data, size, a.width, a.y0, a.y1), c), the message's pixels
// decoded as the merge reaches them instead of into a pixel set first; `received` is their count.
ActivePixels merge_active_sparse(const ActivePixels& a, const std::uint8_t* data, std::size_t size,
                                 Counters& c, std::uint64_t& received);

// Writes a pixel set into a frame buffer holding (at least) its rows, without comparisons.
void scatter_active(const ActivePixels& a, Framebuffer& fb);

} // namespace zc
