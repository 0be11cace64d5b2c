#pragma once
// The depth buffer's recently entered lines (docs/machines.md, "The order of the triangles"): a
// window over the 64-byte lines (16 locations of 4-byte depths) of a frame buffer's depth array,
// direct-mapped, that the z-buffer enters span by span. A line not in the window when a span
// enters it is a far line: on a host whose cache holds about a megabyte of the frame buffer's
// recently drawn rows (depth, ids and colours), a line fetched from beyond that cache. Triangles
// in an order with locality (a mesh in strip order) draw near the lines their predecessors
// entered; a scattered order enters far ones. Exact integers: the same count on every host.
#include <cstdint>
#include <vector>

namespace zc {

class RecentLines {
public:
  static constexpr std::size_t kLocations = 16; // locations a line (64 bytes of depth)
  static constexpr std::size_t kWindow = 8192;  // lines the window holds: 512 KiB of depth

  // The window after a clear of `locations` locations: the clear entered every line in order, so
  // each slot holds the last line of the buffer that maps to it (a buffer of at most kWindow lines
  // is then all in the window).
  void reset(std::size_t locations) {
    lines_ = (locations + kLocations - 1) / kLocations;
    tags_.clear(); // filled at the first enter(): a buffer no z-buffer draws allocates nothing
  }

  // Enters the lines of locations [first, last] (first <= last); returns how many were not in the
  // window (they are in it afterwards).
  std::uint64_t enter(std::size_t first, std::size_t last) {
    if (tags_.empty()) fill();
    std::uint64_t far = 0;
    for (std::size_t l = first / kLocations; l <= last / kLocations; ++l) {
      // A buffer of fewer than kWindow lines has a slot a line: l & (kWindow - 1) is l.
      std::uint32_t& slot = tags_[l & (kWindow - 1)];
      if (slot != std::uint32_t(l)) {
        slot = std::uint32_t(l);
        ++far;
      }
    }
    return far;
  }

private:
  void fill() {
    const std::size_t n = lines_ < kWindow ? lines_ : kWindow;
    tags_.resize(n == 0 ? 1 : n);
    for (std::size_t j = 0; j < n; ++j)
      tags_[j] = std::uint32_t(j + kWindow * ((lines_ - 1 - j) / kWindow));
  }

  std::size_t lines_ = 0;           // lines of the buffer
  std::vector<std::uint32_t> tags_; // the line each slot holds
};

} // namespace zc
