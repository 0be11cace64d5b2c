#include "raster/framebuffer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace zc {

static std::uint8_t to_byte(float c) {
  const float v = c <= 0.f ? 0.f : (c >= 1.f ? 1.f : c);
  return static_cast<std::uint8_t>(std::lround(v * 255.f));
}

Framebuffer::Framebuffer(int width, RowSet rows, glm::vec3 background)
    : width_(width), rows_(rows) {
  clear(background);
}

void Framebuffer::clear(glm::vec3 background) {
  const std::size_t n = std::size_t(width_) * std::size_t(rows_.count());
  recent_.reset(n);
  depth_.assign(n, std::numeric_limits<float>::infinity());
  ids_.assign(n, kNoTriangle);
  const std::uint8_t bg[3] = {to_byte(background.x), to_byte(background.y), to_byte(background.z)};
  if (bg[0] == bg[1] && bg[1] == bg[2]) {
    rgb_.assign(3 * n, bg[0]); // a grey background (black, usually) is one memset
    return;
  }
  rgb_.resize(3 * n);
  if (n == 0) return; // a band of zero rows (more nodes than rows) has no first row to copy
  const std::size_t row = 3 * std::size_t(width_);
  for (std::size_t i = 0; i < std::size_t(width_); ++i)
    std::memcpy(&rgb_[3 * i], bg, 3);
  for (std::size_t r = 1; r < std::size_t(rows_.count()); ++r)
    std::memcpy(&rgb_[r * row], rgb_.data(), row);
}

void Framebuffer::clear_rows(int y0, int y1, glm::vec3 background) {
  const int r0 = rows_.local(rows_.first_from(y0));
  const int r1 = rows_.local(rows_.first_from(std::min(y1, rows_.end)));
  if (r1 <= r0) return;
  const std::size_t a = std::size_t(r0) * width_, b = std::size_t(r1) * width_;
  std::fill(depth_.begin() + a, depth_.begin() + b, std::numeric_limits<float>::infinity());
  std::fill(ids_.begin() + a, ids_.begin() + b, kNoTriangle);
  const std::uint8_t bg[3] = {to_byte(background.x), to_byte(background.y), to_byte(background.z)};
  if (bg[0] == bg[1] && bg[1] == bg[2]) {
    std::memset(rgb_.data() + 3 * a, bg[0], 3 * (b - a));
    return;
  }
  for (std::size_t i = a; i < b; ++i)
    std::memcpy(&rgb_[3 * i], bg, 3);
}

std::uint64_t Framebuffer::merge(const Framebuffer& o) {
  if (o.width_ != width_ || o.ids_.size() != ids_.size())
    throw std::logic_error("Framebuffer::merge: shapes differ");
  std::uint64_t compares = 0;
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    if (o.ids_[i] == kNoTriangle) continue;
    ++compares;
    test_and_write(i, o.depth_[i], o.ids_[i], &o.rgb_[3 * i]);
  }
  return compares;
}

std::vector<std::uint8_t> Framebuffer::pack_locations(std::size_t first, std::size_t n) const {
  // Appended, not cleared then overwritten: a band of a large picture is a hundred megabytes.
  std::vector<std::uint8_t> out;
  out.reserve(kLocationBytes * n);
  const auto append = [&out](const void* from, std::size_t bytes) {
    const auto* p = static_cast<const std::uint8_t*>(from);
    out.insert(out.end(), p, p + bytes);
  };
  append(rgb_.data() + 3 * first, 3 * n);
  append(depth_.data() + first, 4 * n);
  append(ids_.data() + first, 4 * n);
  return out;
}

std::size_t Framebuffer::merge_locations(const std::uint8_t* msg, std::size_t size,
                                         std::size_t first) {
  const std::size_t n = size / kLocationBytes;
  if (size % kLocationBytes != 0 || first + n > ids_.size())
    throw std::runtime_error("Framebuffer::merge_locations: message does not fit the buffer");
  // Depths and ids read in place (unaligned loads), not copied out into arrays of their own first.
  const std::uint8_t* zs = msg + 3 * n;
  const std::uint8_t* ids = msg + 7 * n;
  for (std::size_t k = 0; k < n; ++k) {
    float z;
    std::uint32_t id;
    std::memcpy(&z, zs + 4 * k, 4);
    std::memcpy(&id, ids + 4 * k, 4);
    test_and_write(first + k, z, id, msg + 3 * k);
  }
  return n;
}

void Framebuffer::paste(const Framebuffer& part) {
  const RowSet& pr = part.rows();
  for (int y = pr.begin; y < pr.end; y += pr.stride) {
    if (!rows_.contains(y)) continue;
    const std::size_t src = std::size_t(pr.local(y)) * width_;
    const std::size_t dst = std::size_t(rows_.local(y)) * width_;
    for (int x = 0; x < width_; ++x) {
      depth_[dst + x] = part.depth_[src + x];
      ids_[dst + x] = part.ids_[src + x];
      for (int k = 0; k < 3; ++k)
        rgb_[3 * (dst + x) + k] = part.rgb_[3 * (src + x) + k];
    }
  }
}

std::uint64_t Framebuffer::covered() const {
  std::uint64_t n = 0;
  for (auto id : ids_)
    n += id != kNoTriangle;
  return n;
}

} // namespace zc
