#pragma once
// A z-buffered frame buffer over a set of rows: the whole screen, a horizontal band (image-space
// decompositions) or every P-th row (Blazek's interleaved lines). Each pixel keeps its colour, its
// depth and the id of the triangle that wrote it: depth ties go to the lower id, which makes the
// final image independent of submission order and of any partition of the work.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "raster/recent_lines.hpp"
#include "util/run_bytes.hpp"

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

// Storage whose resize leaves new elements uninitialised: a frame buffer's rows get their
// background on first touch (Framebuffer::ready_row), so a new buffer's pages are touched, and
// faulted in by the host, only where something is drawn, merged or read.
template <class T> struct NoInitAllocator : std::allocator<T> {
  template <class U> struct rebind { using other = NoInitAllocator<U>; };
  NoInitAllocator() = default;
  template <class U> NoInitAllocator(const NoInitAllocator<U>&) noexcept {}
  template <class U> void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; }
  template <class U, class... A> void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
};
template <class T> using Plane = std::vector<T, NoInitAllocator<T>>;

class Framebuffer {
public:
  Framebuffer() = default;
  Framebuffer(int width, RowSet rows, glm::vec3 background);
  // A copy holds the same pixels; the rows not yet touched stay untouched in the copy.
  Framebuffer(const Framebuffer& o);
  Framebuffer& operator=(const Framebuffer& o);
  Framebuffer(Framebuffer&&) noexcept = default;
  Framebuffer& operator=(Framebuffer&&) noexcept = default;

  // Back to the background, keeping the memory (a renderer drawing many frames pays no page
  // faults for a new buffer each time). Lazy: each row is filled with the background when first
  // touched, so a buffer of which a node draws a few rows costs the host only those rows.
  void clear(glm::vec3 background);
  // The same for rows [y0, y1) of the set only (buffer already sized): threads clearing their own
  // bands.
  void clear_rows(int y0, int y1, glm::vec3 background);

  int width() const { return width_; }
  const RowSet& rows() const { return rows_; }
  std::size_t index(int x, int y) const { return std::size_t(rows_.local(y)) * width_ + x; }

  // Gives row y (a row of the set) its background if it has not been touched yet. Every writer by
  // index (test_and_write, the *_data() pointers) readies the row first; rows of different
  // threads are independent.
  void ready_row(int y) { ready_local(rows_.local(y)); }
  void ready_local(int r) {
    if (stale_[std::size_t(r)]) fill_row(r);
  }

  // Plain z-buffer write into a ready row; returns true when the fragment won.
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
  // The same string as runs: a row not touched yet is a repeated run of each plane's background,
  // not written out (util/run_bytes.hpp).
  RunBytes pack_location_runs(std::size_t first, std::size_t count) const;
  // Z-buffers such a message into the locations from index `first` (test_and_write at each);
  // returns the number of locations it held.
  std::size_t merge_locations(const std::vector<std::uint8_t>& msg, std::size_t first) {
    return merge_locations(msg.data(), msg.size(), first);
  }
  // The same over `size` bytes at `msg` (a run of a larger message, read in place).
  std::size_t merge_locations(const std::uint8_t* msg, std::size_t size, std::size_t first);
  // The same over bytes [at, at + size) of a string of runs (pack_location_runs): a row whose ids
  // are a repeated run of kNoTriangle covers nothing and is skipped unread.
  std::size_t merge_locations(const RunBytes& msg, std::size_t at, std::size_t size,
                              std::size_t first);
  // Copy the rows of `part` (a band or interleaved set) into this buffer (strip pasting).
  void paste(const Framebuffer& part);

  std::uint64_t covered() const; // pixels written by some triangle (TPF)
  std::size_t pixel_count() const { return ids_.size(); }
  std::size_t bytes() const { return ids_.size() * kLocationBytes; }

  // The whole planes, every row readied first (the rows not touched yet get their background).
  Plane<std::uint8_t>& rgb() { return ready_all(), rgb_; }
  const Plane<std::uint8_t>& rgb() const { return ready_all(), rgb_; }
  Plane<float>& depth() { return ready_all(), depth_; }
  const Plane<float>& depth() const { return ready_all(), depth_; }
  Plane<std::uint32_t>& ids() { return ready_all(), ids_; }
  const Plane<std::uint32_t>& ids() const { return ready_all(), ids_; }
  // The planes as they are, for writers that ready each row they touch (the z-buffer's spans) and
  // readers that skip the untouched rows.
  float* depth_data() { return depth_.data(); }
  std::uint32_t* ids_data() { return ids_.data(); }
  std::uint8_t* rgb_data() { return rgb_.data(); }
  const float* depth_data() const { return depth_.data(); }
  const std::uint32_t* ids_data() const { return ids_.data(); }
  const std::uint8_t* rgb_data() const { return rgb_.data(); }
  // True when row y (a row of the set) has not been touched since the clear: all background.
  bool untouched(int y) const { return stale_[std::size_t(rows_.local(y))] != 0; }
  // The background colour (what an untouched row's pixels read as).
  const std::uint8_t* background_rgb() const { return bg_; }
  // The depth lines the z-buffer entered last (draw_batch's far_lines); clear() resets it.
  RecentLines& recent_lines() { return recent_; }

private:
  void fill_row(int r) const;
  // Calls data(plane bytes, count) for each run of rows already touched and fill(background,
  // element size, count) for each run not touched yet, plane by plane, over locations
  // [first, first + n): the walk of pack_locations and pack_location_runs.
  template <class Data, class Fill>
  void for_each_location_run(std::size_t first, std::size_t n, Data data, Fill fill) const;
  // Where the run of locations that starts k after location `first` leaves its row: k plus the
  // locations to the row's end, at most n (merge_locations walks a message row by row).
  std::size_t row_run_end(std::size_t first, std::size_t k, std::size_t n) const {
    const std::size_t W = std::size_t(width_);
    return std::min(n, ((first + k) / W + 1) * W - first);
  }
  // Z-buffers m locations from index `at` (one row or part of one) given by their three planes.
  void merge_row(const std::uint8_t* rgb, const std::uint8_t* zs, const std::uint8_t* ids,
                 std::size_t m, std::size_t at);
  void ready_local_const(int r) const {
    if (stale_[std::size_t(r)]) fill_row(r);
  }
  void fill_row(int r, const std::uint8_t bg[3]) const;
  void ready_all() const;
  void copy_row(const Framebuffer& from, int from_row, int to_row);

  int width_ = 0;
  RowSet rows_;
  // The planes and which local rows still await their background: filling them in is not a change
  // of the pixels, so const readers may do it.
  mutable Plane<std::uint8_t> rgb_;
  mutable Plane<float> depth_;
  mutable Plane<std::uint32_t> ids_;
  mutable std::vector<std::uint8_t> stale_;
  mutable int stale_rows_ = 0; // an upper bound: 0 means every row is ready
  std::uint8_t bg_[3] = {};
  RecentLines recent_;
};

} // namespace zc
