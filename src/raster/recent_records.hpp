#pragma once
// The triangles' set-up records a span loop read last (docs/machines.md, "A span's set-up record"):
// a window of kWindow records, direct-mapped by triangle index, over a batch's ScreenTriangles
// (216 bytes each). A span whose record is not in the window fetches it from memory: kWindow
// records are 1.7 MB, what a host's 2 MB L2 keeps of them beside the loop's other data (the span
// lists, the MSA and the rows' pixels). The set-up wrote the records in order, so the window starts
// with the last kWindow of them (a batch of at most kWindow records is all in it). Exact integers:
// the same count on every host.
#include <cstdint>

#include "raster/recent_lines.hpp"

namespace zc {

class RecentRecords {
public:
  static constexpr std::size_t kWindow = RecentLines::kWindow; // records the window holds

  // The window after the set-up of `records` records in order.
  void reset(std::size_t records) { slots_.reset(records * RecentLines::kLocations); }

  // Reads record `r`: 1 if it was not in the window (it is afterwards), else 0.
  std::uint64_t read(std::size_t r) {
    return slots_.enter(r * RecentLines::kLocations, r * RecentLines::kLocations);
  }

private:
  RecentLines slots_; // one slot a record: RecentLines' lines, one record a line
};

} // namespace zc
