#pragma once
// A z-buffered frame buffer over a set of rows: the whole screen, a horizontal band (image-space
// decompositions) or every P-th row (Blazek's interleaved lines). Each pixel keeps its colour, its
// depth and the id of the triangle that wrote it: depth ties go to the lower id, which makes the
// final image independent of submission order and of any partition of the work.
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "raster/recent_lines.hpp"

namespace zc {

// Rows begin, begin+stride, ... below end.
struct RowSet {
  int begin = 0, end = 0, stride = 1;
  static RowSet all(int height) { return {0, height, 1}; }
  static RowSet band(int y0, int y1) { return {y0, y1, 1}; }
  static RowSet interleaved(int phase, int stride, int height) { return {phase, height, stride}; }
  int count() const { return end > begin ? (end - begin + stride - 1) / stride : 0; }
  bool contains(int y) const { return y >= begin && y < end && (y - begin) % stride == 0; }
  // (Contiguous rows, the common case, skip the integer division: it is per span.)
  int local(int y) const { return stride == 1 ? y - begin : (y - begin) / stride; }
  // First row of the set at or after y.
  int first_from(int y) const {
    if (y <= begin) return begin;
    if (stride == 1) return y;
    return begin + ((y - begin + stride - 1) / stride) * stride;
  }
};

constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

// True when fragment (z, id) is in front of the stored (zs, ids): the one depth order of zcube.
inline bool in_front(float z, std::uint32_t id, float zs, std::uint32_t ids) {
  return z < zs || (z == zs && id < ids);
}

class Framebuffer {
public:
  Framebuffer() = default;
  Framebuffer(int width, RowSet rows, glm::vec3 background);

  // Back to the background, keeping the memory (a renderer drawing many frames pays no page
  // faults for a new buffer each time).
  void clear(glm::vec3 background);
  // The same for rows [y0, y1) of the set only (buffer already sized): threads clearing their own
  // bands.
  void clear_rows(int y0, int y1, glm::vec3 background);

  int width() const { return width_; }
  const RowSet& rows() const { return rows_; }
  std::size_t index(int x, int y) const { return std::size_t(rows_.local(y)) * width_ + x; }

  // Plain z-buffer write; returns true when the fragment won.
  bool test_and_write(std::size_t i, float z, std::uint32_t id, const std::uint8_t rgb[3]) {
    if (!in_front(z, id, depth_[i], ids_[i])) return false;
    depth_[i] = z;
    ids_[i] = id;
    rgb_[3 * i] = rgb[0];
    rgb_[3 * i + 1] = rgb[1];
    rgb_[3 * i + 2] = rgb[2];
    return true;
  }

  // Merge another buffer over the same rows, pixel by pixel (test_and_write, the one z-merge).
  // Returns the number of comparisons made (the other's covered pixels).
  std::uint64_t merge(const Framebuffer& other);

  // The wire format of full z-buffer locations (hierarchical merge, full z-buffer merging):
  // `count` locations from index `first` as three planes, rgb (3 bytes each), depth (4), id (4),
  // kLocationBytes a location.
  static constexpr std::size_t kLocationBytes = 11;
  std::vector<std::uint8_t> pack_locations(std::size_t first, std::size_t count) const;
  // Z-buffers such a message into the locations from index `first` (test_and_write at each);
  // returns the number of locations it held.
  std::size_t merge_locations(const std::vector<std::uint8_t>& msg, std::size_t first) {
    return merge_locations(msg.data(), msg.size(), first);
  }
  // The same over `size` bytes at `msg` (a run of a larger message, read in place).
  std::size_t merge_locations(const std::uint8_t* msg, std::size_t size, std::size_t first);
  // Copy the rows of `part` (a band or interleaved set) into this buffer (strip pasting).
  void paste(const Framebuffer& part);

  std::uint64_t covered() const; // pixels written by some triangle (TPF)
  std::size_t pixel_count() const { return ids_.size(); }
  std::size_t bytes() const { return ids_.size() * kLocationBytes; }

  std::vector<std::uint8_t>& rgb() { return rgb_; }
  const std::vector<std::uint8_t>& rgb() const { return rgb_; }
  std::vector<float>& depth() { return depth_; }
  const std::vector<float>& depth() const { return depth_; }
  std::vector<std::uint32_t>& ids() { return ids_; }
  const std::vector<std::uint32_t>& ids() const { return ids_; }
  // The depth lines the z-buffer entered last (draw_batch's far_lines); clear() resets it.
  RecentLines& recent_lines() { return recent_; }

private:
  int width_ = 0;
  RowSet rows_;
  std::vector<std::uint8_t> rgb_;
  std::vector<float> depth_;
  std::vector<std::uint32_t> ids_;
  RecentLines recent_;
};

} // namespace zc
