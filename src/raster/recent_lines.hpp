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
  // Lines the last-level-cache window holds: 1 MiB of depth, 2.75 MiB of frame buffer with the ids
  // and colours beside it: the share of the last-level cache one process got on the 2-core virtual
  // machine the probe was validated on (a random walk over 2 MB stayed in it, one over 4-8 MB
  // did not; its nominal 32 MB is shared with other machines: docs/machines.md, "Distant
  // lines"). A far line found in it came from that cache; one not found, a distant line, from
  // main memory.
  static constexpr std::size_t kLlcWindow = 16384;

  // The windows after a clear of `locations` locations: the clear entered every line in order, so
  // each slot holds the last line of the buffer that maps to it (a buffer of at most kWindow lines
  // is then all in the window, one of at most kLlcWindow all in the last-level-cache window).
  void reset(std::size_t locations) {
    lines_ = (locations + kLocations - 1) / kLocations;
    tags_.clear(); // filled at the first enter(): a buffer no z-buffer draws allocates nothing
    llc_tags_.clear();
  }

  // Enters the lines of locations [first, last] (first <= last); returns how many were not in the
  // window (they are in it afterwards). With `distant`, adds to it those of them that were not in
  // the last-level-cache window either (a window kept only by callers that ask for it: every
  // enter() of a buffer must then ask).
  std::uint64_t enter(std::size_t first, std::size_t last, std::uint64_t* distant = nullptr) {
    if (tags_.empty()) fill(tags_, kWindow);
    const bool llc = distant && lines_ > kLlcWindow;
    if (llc && llc_tags_.empty()) fill(llc_tags_, kLlcWindow);
    std::uint64_t far = 0;
    for (std::size_t l = first / kLocations; l <= last / kLocations; ++l) {
      // A buffer of fewer than kWindow lines has a slot a line: l & (kWindow - 1) is l.
      std::uint32_t& slot = tags_[l & (kWindow - 1)];
      if (slot == std::uint32_t(l)) continue;
      slot = std::uint32_t(l);
      ++far;
      // Lines sharing a last-level slot share a window slot (kWindow divides kLlcWindow): a line
      // in the window is in the last-level window too, so only a far line looks there.
      if (!llc) continue;
      std::uint32_t& big = llc_tags_[l & (kLlcWindow - 1)];
      if (big != std::uint32_t(l)) {
        big = std::uint32_t(l);
        ++*distant;
      }
    }
    return far;
  }

private:
  void fill(std::vector<std::uint32_t>& tags, std::size_t window) const {
    const std::size_t n = lines_ < window ? lines_ : window;
    tags.resize(n == 0 ? 1 : n);
    for (std::size_t j = 0; j < n; ++j)
      tags[j] = std::uint32_t(j + window * ((lines_ - 1 - j) / window));
  }

  std::size_t lines_ = 0;               // lines of the buffer
  std::vector<std::uint32_t> tags_;     // the line each slot holds
  std::vector<std::uint32_t> llc_tags_; // the same, in the last-level-cache window
};

} // namespace zc
