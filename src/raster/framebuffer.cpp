#include "raster/framebuffer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "raster/avx2_lanes.hpp"

namespace zc {

namespace {
#ifdef ZC_HAVE_AVX2_LANES
// The first locations of a message's run (a multiple of eight, all but the last n % 8) z-buffered
// into the planes at `depth`, `ids` and `rgb`, whose rows are ready: eight at once, each as
// test_and_write would (the locations are distinct, so the lanes are independent). in_front over
// eight lanes: z < zs (ordered: false for NaN), or z == zs and id < ids (unsigned, compared signed
// after flipping the sign bits). Returns how many it merged.
__attribute__((target("avx2"))) std::size_t
merge_eights_avx2(std::size_t n, const std::uint8_t* zs, const std::uint8_t* idm,
                  const std::uint8_t* rgbm, float* depth, std::uint32_t* ids, std::uint8_t* rgb) {
  const __m256i sign = _mm256_set1_epi32(int(0x80000000u));
  std::size_t k = 0;
  for (; k + 8 <= n; k += 8) {
    const __m256 z = _mm256_loadu_ps(reinterpret_cast<const float*>(zs + 4 * k));
    const __m256 zd = _mm256_loadu_ps(depth + k);
    const __m256i id = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(idm + 4 * k));
    const __m256i idd = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(ids + k));
    const __m256 id_lt = _mm256_castsi256_ps(
        _mm256_cmpgt_epi32(_mm256_xor_si256(idd, sign), _mm256_xor_si256(id, sign)));
    const __m256 wins = _mm256_or_ps(_mm256_cmp_ps(z, zd, _CMP_LT_OQ),
                                     _mm256_and_ps(_mm256_cmp_ps(z, zd, _CMP_EQ_OQ), id_lt));
    unsigned mask = unsigned(_mm256_movemask_ps(wins));
    if (mask == 0) continue;
    _mm256_maskstore_ps(depth + k, _mm256_castps_si256(wins), z);
    _mm256_maskstore_epi32(reinterpret_cast<int*>(ids + k), _mm256_castps_si256(wins), id);
    for (; mask != 0; mask &= mask - 1) {
      const std::size_t j = k + std::size_t(__builtin_ctz(mask));
      std::memcpy(rgb + 3 * j, rgbm + 3 * j, 3);
    }
  }
  return k;
}
#endif
} // namespace

static std::uint8_t to_byte(float c) {
  const float v = c <= 0.f ? 0.f : (c >= 1.f ? 1.f : c);
  return static_cast<std::uint8_t>(std::lround(v * 255.f));
}

Framebuffer::Framebuffer(int width, RowSet rows, glm::vec3 background)
    : width_(width), rows_(rows) {
  clear(background);
}

Framebuffer::Framebuffer(const Framebuffer& o)
    : width_(o.width_), rows_(o.rows_), rgb_(o.rgb_.size()), depth_(o.depth_.size()),
      ids_(o.ids_.size()), stale_(o.stale_.size(), 1), stale_rows_(int(o.stale_.size())),
      recent_(o.recent_) {
  std::memcpy(bg_, o.bg_, 3);
  for (int r = 0; r < int(stale_.size()); ++r)
    if (!o.stale_[std::size_t(r)]) copy_row(o, r, r);
}

Framebuffer& Framebuffer::operator=(const Framebuffer& o) {
  if (this != &o) *this = Framebuffer(o);
  return *this;
}

void Framebuffer::clear(glm::vec3 background) {
  const std::size_t n = std::size_t(width_) * std::size_t(rows_.count());
  recent_.reset(n);
  // Resized without writing: the rows are filled in as they are touched (ready_row).
  depth_.resize(n);
  ids_.resize(n);
  rgb_.resize(3 * n);
  bg_[0] = to_byte(background.x);
  bg_[1] = to_byte(background.y);
  bg_[2] = to_byte(background.z);
  stale_.assign(std::size_t(rows_.count()), 1);
  stale_rows_ = rows_.count();
}

void Framebuffer::fill_row(int r) const {
  fill_row(r, bg_);
}

void Framebuffer::fill_row(int r, const std::uint8_t bg[3]) const {
  const std::size_t a = std::size_t(r) * width_, b = a + width_;
  std::fill(depth_.begin() + a, depth_.begin() + b, std::numeric_limits<float>::infinity());
  std::fill(ids_.begin() + a, ids_.begin() + b, kNoTriangle);
  if (bg[0] == bg[1] && bg[1] == bg[2]) {
    std::memset(rgb_.data() + 3 * a, bg[0], 3 * (b - a)); // a grey background (black, usually)
  } else {
    for (std::size_t i = a; i < b; ++i)
      std::memcpy(&rgb_[3 * i], bg, 3);
  }
  stale_[std::size_t(r)] = 0;
}

void Framebuffer::ready_all() const {
  if (stale_rows_ == 0) return;
  for (int r = 0; r < int(stale_.size()); ++r)
    if (stale_[std::size_t(r)]) fill_row(r);
  stale_rows_ = 0;
}

void Framebuffer::copy_row(const Framebuffer& from, int from_row, int to_row) {
  const std::size_t W = std::size_t(width_);
  const std::size_t src = std::size_t(from_row) * W, dst = std::size_t(to_row) * W;
  std::memcpy(&depth_[dst], &from.depth_[src], 4 * W);
  std::memcpy(&ids_[dst], &from.ids_[src], 4 * W);
  std::memcpy(&rgb_[3 * dst], &from.rgb_[3 * src], 3 * W);
  stale_[std::size_t(to_row)] = 0;
}

void Framebuffer::clear_rows(int y0, int y1, glm::vec3 background) {
  const int r0 = rows_.local(rows_.first_from(y0));
  const int r1 = rows_.local(rows_.first_from(std::min(y1, rows_.end)));
  const std::uint8_t bg[3] = {to_byte(background.x), to_byte(background.y), to_byte(background.z)};
  // Filled now, not left for first touch: threads clear their own bands of one buffer, and the
  // buffer's background and count of stale rows are not theirs to change.
  for (int r = r0; r < r1; ++r)
    fill_row(r, bg);
}

std::uint64_t Framebuffer::merge(const Framebuffer& o) {
  if (o.width_ != width_ || o.ids_.size() != ids_.size())
    throw std::logic_error("Framebuffer::merge: shapes differ");
  std::uint64_t compares = 0;
  const std::size_t W = std::size_t(width_);
  for (int r = 0; r < int(stale_.size()); ++r) {
    if (o.stale_[std::size_t(r)]) continue; // all background: nothing covered to compare
    ready_local(r);
    for (std::size_t i = std::size_t(r) * W; i < std::size_t(r + 1) * W; ++i) {
      if (o.ids_[i] == kNoTriangle) continue;
      ++compares;
      test_and_write(i, o.depth_[i], o.ids_[i], &o.rgb_[3 * i]);
    }
  }
  return compares;
}

template <class Data, class Fill>
void Framebuffer::for_each_location_run(std::size_t first, std::size_t n, Data data,
                                        Fill fill) const {
  const std::size_t W = std::size_t(width_), end = first + n;
  const auto plane = [&](const void* bytes, std::size_t size, const void* background) {
    const auto* p = static_cast<const std::uint8_t*>(bytes);
    for (std::size_t i = first; i < end;) {
      const std::size_t r = i / W, to = std::min(end, (r + 1) * W);
      if (!stale_[r])
        data(p + size * i, size * (to - i));
      else
        fill(static_cast<const std::uint8_t*>(background), size, size * (to - i));
      i = to;
    }
  };
  const float inf = std::numeric_limits<float>::infinity();
  plane(rgb_.data(), 3, bg_);
  plane(depth_.data(), 4, &inf);
  plane(ids_.data(), 4, &kNoTriangle);
}

std::vector<std::uint8_t> Framebuffer::pack_locations(std::size_t first, std::size_t n) const {
  // Appended, not cleared then overwritten: a band of a large picture is a hundred megabytes.
  std::vector<std::uint8_t> out;
  out.reserve(kLocationBytes * n);
  // A row not touched yet is sent as its background, without filling it in here.
  const auto data = [&](const std::uint8_t* p, std::size_t bytes) {
    out.insert(out.end(), p, p + bytes);
  };
  const auto fill = [&](const std::uint8_t* bg, std::size_t size, std::size_t bytes) {
    if (bg[0] == bg[1] && bg[1] == bg[2] && (size < 4 || bg[2] == bg[3])) {
      out.insert(out.end(), bytes, bg[0]);
      return;
    }
    const std::size_t at = out.size();
    out.resize(at + bytes);
    for (std::size_t k = at; k < out.size(); k += size)
      std::memcpy(&out[k], bg, size);
  };
  for_each_location_run(first, n, data, fill);
  return out;
}

RunBytes Framebuffer::pack_location_runs(std::size_t first, std::size_t n) const {
  RunBytes out;
  std::size_t written = 0;
  for_each_location_run(
      first, n, [&](const std::uint8_t*, std::size_t bytes) { written += bytes; },
      [](const std::uint8_t*, std::size_t, std::size_t) {});
  out.reserve(written);
  for_each_location_run(
      first, n, [&](const std::uint8_t* p, std::size_t bytes) { out.append(p, bytes); },
      [&](const std::uint8_t* bg, std::size_t size, std::size_t bytes) {
        out.append_fill(bg, size, bytes);
      });
  return out;
}

namespace {

// True when the n locations of a message run at `ids` (unaligned 4-byte ids) are all uncovered.
bool all_uncovered(const std::uint8_t* ids, std::size_t n) {
  for (std::size_t k = 0; k < 4 * n; ++k)
    if (ids[k] != 0xff) return false;
  return true;
}

} // namespace

std::size_t Framebuffer::merge_locations(const std::uint8_t* msg, std::size_t size,
                                         std::size_t first) {
  const std::size_t n = size / kLocationBytes;
  if (size % kLocationBytes != 0 || first + n > ids_.size())
    throw std::runtime_error("Framebuffer::merge_locations: message does not fit the buffer");
  // Depths and ids read in place (unaligned loads), not copied out into arrays of their own first.
  const std::uint8_t* zs = msg + 3 * n;
  const std::uint8_t* ids = msg + 7 * n;
  for (std::size_t k = 0; k < n;) {
    const std::size_t to = row_run_end(first, k, n);
    merge_row(msg + 3 * k, zs + 4 * k, ids + 4 * k, to - k, first + k);
    k = to;
  }
  return n;
}

std::size_t Framebuffer::merge_locations(const RunBytes& msg, std::size_t at, std::size_t size,
                                         std::size_t first) {
  const std::size_t n = size / kLocationBytes;
  if (size % kLocationBytes != 0 || first + n > ids_.size() || at + size > msg.size())
    throw std::runtime_error("Framebuffer::merge_locations: message does not fit the buffer");
  std::vector<std::uint8_t> row; // a row whose planes are not all written runs, written out
  for (std::size_t k = 0; k < n;) {
    const std::size_t to = row_run_end(first, k, n), m = to - k;
    const std::size_t rgb_at = at + 3 * k, zs_at = at + 3 * n + 4 * k, ids_at = at + 7 * n + 4 * k;
    if (msg.is_fill_of(ids_at, 4 * m, 0xff)) { // uncovered: never in front
      k = to;
      continue;
    }
    const std::uint8_t *rgb = msg.find(rgb_at, 3 * m), *zs = msg.find(zs_at, 4 * m),
                       *ids = msg.find(ids_at, 4 * m);
    if (!rgb || !zs || !ids) {
      row.resize(kLocationBytes * m);
      msg.copy(rgb_at, 3 * m, row.data());
      msg.copy(zs_at, 4 * m, row.data() + 3 * m);
      msg.copy(ids_at, 4 * m, row.data() + 7 * m);
      rgb = row.data(), zs = row.data() + 3 * m, ids = row.data() + 7 * m;
    }
    merge_row(rgb, zs, ids, m, first + k);
    k = to;
  }
  return n;
}

void Framebuffer::merge_row(const std::uint8_t* rgb, const std::uint8_t* zs,
                            const std::uint8_t* ids, std::size_t m, std::size_t at) {
  // An uncovered location never wins (in_front against the background is false), so a row not
  // touched yet stays untouched when the message's part of it covers nothing.
  const std::size_t r = at / std::size_t(width_);
  if (stale_[r] && all_uncovered(ids, m)) return;
  ready_local(int(r));
  std::size_t k = 0;
#ifdef ZC_HAVE_AVX2_LANES
  if (avx2::available())
    k = merge_eights_avx2(m, zs, ids, rgb, depth_.data() + at, ids_.data() + at,
                          rgb_.data() + 3 * at);
#endif
  for (; k < m; ++k) {
    float z;
    std::uint32_t id;
    std::memcpy(&z, zs + 4 * k, 4);
    std::memcpy(&id, ids + 4 * k, 4);
    test_and_write(at + k, z, id, rgb + 3 * k);
  }
}

void Framebuffer::paste(const Framebuffer& part) {
  const RowSet& pr = part.rows();
  for (int y = pr.begin; y < pr.end; y += pr.stride) {
    if (!rows_.contains(y)) continue;
    const int from = pr.local(y), to = rows_.local(y);
    if (part.stale_[std::size_t(from)] && std::memcmp(part.bg_, bg_, 3) == 0) {
      stale_[std::size_t(to)] = 1; // the same background, still to be filled in
      ++stale_rows_;
      continue;
    }
    part.ready_local_const(from);
    copy_row(part, from, to);
  }
}

std::uint64_t Framebuffer::covered() const {
  std::uint64_t n = 0;
  const std::size_t W = std::size_t(width_);
  for (std::size_t r = 0; r < stale_.size(); ++r)
    if (!stale_[r])
      for (std::size_t i = r * W; i < (r + 1) * W; ++i)
        n += ids_[i] != kNoTriangle;
  return n;
}

} // namespace zc
