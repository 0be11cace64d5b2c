#include "raster/zbuffer.hpp"

#include <cstring>

#include "raster/avx2_lanes.hpp"

namespace zc {

namespace {

// floor(n / d) and the remainder in [0, d), for d > 0, exactly, without a 64-bit divide: the
// quotient from a double reciprocal is within 1 of the true one for |n| < 2^56 (a few units in
// the last place of a quotient below 2^48), and integer remainders settle it.
inline void floor_divmod(std::int64_t n, std::int64_t d, double inv_d, std::int64_t& q,
                         std::int64_t& r) {
  q = std::int64_t(double(n) * inv_d);
  r = n - q * d;
  while (r < 0) {
    --q;
    r += d;
  }
  while (r >= d) {
    ++q;
    r -= d;
  }
}

} // namespace

EdgeWalk::EdgeWalk(const ScreenTriangle& t, int e, int y, int stride) {
  const std::int64_t py = std::int64_t(y) * kSub + kSub / 2;
  const std::int64_t K = t.A[e] * (kSub / 2) + t.B[e] * py + t.C[e] - t.bias[e];
  const std::int64_t dK = t.B[e] * kSub * stride;
  sign_ = t.A[e] > 0 ? 1 : (t.A[e] < 0 ? -1 : 0);
  d_ = sign_ == 0 ? 1 : (t.A[e] > 0 ? t.A[e] : -t.A[e]) * kSub;
  const double inv_d = 1.0 / double(d_);
  floor_divmod(K, d_, inv_d, q_, r_);
  floor_divmod(dK, d_, inv_d, dq_, dr_);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define ZC_NARROW_SCAN_AVX2 1
#endif

bool NarrowScan::init(const ScreenTriangle& t, const RowSet& rows, int y, int yend) {
#ifdef ZC_NARROW_SCAN_AVX2
  if (!avx2::available() || t.bx1 < t.bx0 || t.bx1 - t.bx0 >= kMaxColumns) return false;
  x0_ = t.bx0;
  columns_ = t.bx1 - t.bx0 + 1;
  y_ = y;
  yend_ = yend;
  stride_ = rows.stride;
  const std::int64_t lanes = (columns_ + 7) / 8 * 8; // columns evaluated, the box's and beyond
  const std::int64_t rows_n = (yend - y + stride_ - 1) / stride_;
  constexpr std::int64_t kLimit = std::int64_t(1) << 30;
  for (int e = 0; e < 3; ++e) {
    const std::int64_t px = std::int64_t(x0_) * kSub + kSub / 2;
    const std::int64_t py = std::int64_t(y) * kSub + kSub / 2;
    const std::int64_t e0 = t.A[e] * px + t.B[e] * py + t.C[e] - t.bias[e];
    const std::int64_t dx = t.A[e] * kSub, dy = t.B[e] * kSub * stride_;
    // Linear over the box: its largest magnitude is at a corner, and every value between.
    const std::int64_t ex = e0 + dx * (lanes - 1), ey = dy * (rows_n - 1);
    for (std::int64_t v : {e0, ex, e0 + ey, ex + ey})
      if (v >= kLimit || v <= -kLimit) return false;
    if (dx >= kLimit || dx <= -kLimit || dy >= kLimit || dy <= -kLimit) return false;
    e_[e] = std::int32_t(e0);
    dx_[e] = std::int32_t(dx);
    dy_[e] = std::int32_t(dy);
  }
  return true;
#else
  (void)t, (void)rows, (void)y, (void)yend;
  return false;
#endif
}

#ifdef ZC_NARROW_SCAN_AVX2
__attribute__((target("avx2"))) bool NarrowScan::next(SpanBatch& b) {
  b.n = 0;
  const int nv = (columns_ + 7) / 8; // vectors of 8 columns
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i minus1 = _mm256_set1_epi32(-1);
  __m256i live[kMaxColumns / 8], ev[3][kMaxColumns / 8], dy[3];
  for (int v = 0; v < nv; ++v)
    live[v] = _mm256_cmpgt_epi32(_mm256_set1_epi32(columns_ - 8 * v), lane);
  for (int e = 0; e < 3; ++e) {
    const __m256i dx = _mm256_set1_epi32(dx_[e]);
    for (int v = 0; v < nv; ++v)
      ev[e][v] = _mm256_add_epi32(
          _mm256_set1_epi32(e_[e]),
          _mm256_mullo_epi32(dx, _mm256_add_epi32(lane, _mm256_set1_epi32(8 * v))));
    dy[e] = _mm256_set1_epi32(dy_[e]);
  }
  for (; y_ < yend_ && b.n < SpanBatch::kMax; y_ += stride_) {
    std::uint32_t m = 0;
    for (int v = 0; v < nv; ++v) {
      __m256i in = live[v];
      for (int e = 0; e < 3; ++e) {
        in = _mm256_and_si256(in, _mm256_cmpgt_epi32(ev[e][v], minus1));
        ev[e][v] = _mm256_add_epi32(ev[e][v], dy[e]);
      }
      m |= std::uint32_t(_mm256_movemask_ps(_mm256_castsi256_ps(in))) << (8 * v);
    }
    if (m == 0) continue;
    b.y[b.n] = y_;
    b.x0[b.n] = x0_ + __builtin_ctz(m);
    b.x1[b.n] = x0_ + 31 - __builtin_clz(m);
    ++b.n;
  }
  // Where the rows scanned so far leave the edge functions, for a next call.
  for (int e = 0; e < 3; ++e)
    e_[e] = _mm256_extract_epi32(ev[e][0], 0);
  return b.n > 0;
}
#else
bool NarrowScan::next(SpanBatch& b) {
  b.n = 0;
  return false;
}
#endif

namespace {

// The constants of one untextured triangle's span loop, in locals: the colour stores go through
// uint8_t pointers, which may alias anything, so values read through references would be reloaded
// after every pixel.
struct FlatSpan {
  float* depth;
  std::uint32_t* ids;
  std::uint8_t* rgb;
  double zax, rax, gax, bax;
  glm::vec3 kd;
  std::uint32_t id;
};

// Pixels [x0, x1] of one row from index i, one at a time: the same arithmetic, in the same order,
// as RowShader (depth, then (r0 + ax*x) * kd per channel).
void flat_span(const FlatSpan& s, const double (&row)[4], int x0, int x1, std::size_t i,
               std::uint64_t& written, std::uint64_t& first) {
  for (int x = x0; x <= x1; ++x, ++i) {
    const float z = static_cast<float>(row[0] + s.zax * x);
    if (!in_front(z, s.id, s.depth[i], s.ids[i])) continue;
    const float r = float(row[1] + s.rax * x) * s.kd.x;
    const float g = float(row[2] + s.gax * x) * s.kd.y;
    const float b = float(row[3] + s.bax * x) * s.kd.z;
    first += s.ids[i] == kNoTriangle;
    s.depth[i] = z;
    s.ids[i] = s.id;
    s.rgb[3 * i] = unit_to_byte(r);
    s.rgb[3 * i + 1] = unit_to_byte(g);
    s.rgb[3 * i + 2] = unit_to_byte(b);
    ++written;
  }
}

#ifdef ZC_HAVE_AVX2_LANES
#define ZC_FLAT_SPAN_AVX2 1
// flat_span's pixels eight at a time (raster/avx2_lanes.hpp: bit for bit the scalar loop).
__attribute__((target("avx2"))) void flat_span_avx2(const FlatSpan& s, const double (&row)[4],
                                                    int x0, int x1, std::size_t i,
                                                    std::uint64_t& written, std::uint64_t& first) {
  const __m256d zax = _mm256_set1_pd(s.zax), rax = _mm256_set1_pd(s.rax);
  const __m256d gax = _mm256_set1_pd(s.gax), bax = _mm256_set1_pd(s.bax);
  const __m256 kr = _mm256_set1_ps(s.kd.x), kg = _mm256_set1_ps(s.kd.y);
  const __m256 kb = _mm256_set1_ps(s.kd.z);
  const __m256i sign = _mm256_set1_epi32(std::int32_t(0x80000000u));
  const __m256i id = _mm256_set1_epi32(std::int32_t(s.id));
  const __m256i id_biased = _mm256_xor_si256(id, sign);
  const __m256i none = _mm256_set1_epi32(-1); // kNoTriangle
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i pack3 = _mm256_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1, 0,
                                         1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1);
  for (int x = x0; x <= x1; x += 8, i += 8) {
    const __m256i live = _mm256_cmpgt_epi32(_mm256_set1_epi32(x1 - x + 1), lane);
    const avx2::Columns xs = avx2::columns8(x);
    const __m256 z = avx2::plane8(row[0], zax, xs);
    const __m256 zs = _mm256_maskload_ps(s.depth + i, live);
    const __m256i ids = _mm256_maskload_epi32(reinterpret_cast<const int*>(s.ids + i), live);
    // in_front: z < zs, or z == zs and id < ids (unsigned: compared with the sign bit flipped).
    const __m256i id_lt = _mm256_cmpgt_epi32(_mm256_xor_si256(ids, sign), id_biased);
    const __m256 lt = _mm256_cmp_ps(z, zs, _CMP_LT_OQ);
    const __m256 eq = _mm256_cmp_ps(z, zs, _CMP_EQ_OQ);
    const __m256i win =
        _mm256_and_si256(live, _mm256_or_si256(_mm256_castps_si256(lt),
                                               _mm256_and_si256(_mm256_castps_si256(eq), id_lt)));
    const int m = _mm256_movemask_ps(_mm256_castsi256_ps(win));
    if (m == 0) continue;
    // Each lane's colour as r | g << 8 | b << 16 (the bytes are 0..255), then the three bytes of
    // each of a 128-bit half's four pixels packed into its low 12 bytes.
    const __m256i r = avx2::to_bytes8(_mm256_mul_ps(avx2::plane8(row[1], rax, xs), kr));
    const __m256i g = avx2::to_bytes8(_mm256_mul_ps(avx2::plane8(row[2], gax, xs), kg));
    const __m256i b = avx2::to_bytes8(_mm256_mul_ps(avx2::plane8(row[3], bax, xs), kb));
    const __m256i px =
        _mm256_or_si256(r, _mm256_or_si256(_mm256_slli_epi32(g, 8), _mm256_slli_epi32(b, 16)));
    std::uint8_t* const out = s.rgb + 3 * i;
    if (m == 0xff) { // all eight pixels won: 24 bytes in four stores
      const __m256i rgb = _mm256_shuffle_epi8(px, pack3);
      const __m128i lo = _mm256_castsi256_si128(rgb), hi = _mm256_extracti128_si256(rgb, 1);
      _mm_storel_epi64(reinterpret_cast<__m128i*>(out), lo);
      const std::int32_t lo_tail = _mm_extract_epi32(lo, 2), hi_tail = _mm_extract_epi32(hi, 2);
      std::memcpy(out + 8, &lo_tail, 4);
      _mm_storel_epi64(reinterpret_cast<__m128i*>(out + 12), hi);
      std::memcpy(out + 20, &hi_tail, 4);
    } else {
      alignas(32) std::int32_t c[8];
      _mm256_store_si256(reinterpret_cast<__m256i*>(c), px);
      for (int k = 0; k < 8; ++k)
        if (m >> k & 1) std::memcpy(out + 3 * k, &c[k], 3);
    }
    const int fresh = _mm256_movemask_ps(
        _mm256_castsi256_ps(_mm256_and_si256(win, _mm256_cmpeq_epi32(ids, none))));
    _mm256_maskstore_ps(s.depth + i, win, z);
    _mm256_maskstore_epi32(reinterpret_cast<int*>(s.ids + i), win, id);
    first += std::uint64_t(__builtin_popcount(unsigned(fresh)));
    written += std::uint64_t(__builtin_popcount(unsigned(m)));
  }
}

#endif

FlatSpan flat(const ScreenTriangle& t, const ShadeContext& ctx, Framebuffer& fb) {
  return {fb.depth_data(),
          fb.ids_data(),
          fb.rgb_data(),
          t.z.ax,
          t.r.ax,
          t.g.ax,
          t.b.ax,
          (*ctx.materials)[t.material].kd,
          t.id};
}

// One span of an untextured triangle: its start values, then its pixels.
void flat_row(const ScreenTriangle& t, const FlatSpan& s, int y, int x0, int x1, Framebuffer& fb,
              std::uint64_t& written, std::uint64_t& first) {
  const double row[4] = {t.z.row(y), t.r.row(y), t.g.row(y), t.b.row(y)};
  const std::size_t i = fb.index(x0, y);
  fb.ready_row(y);
#ifdef ZC_FLAT_SPAN_AVX2
  if (avx2::available() && x1 - x0 >= 2) { // shorter spans: the scalar loop measured faster
    flat_span_avx2(s, row, x0, x1, i, written, first);
    return;
  }
#endif
  flat_span(s, row, x0, x1, i, written, first);
}

// One span of a textured triangle, pixel by pixel through its row shader.
void shaded_row(const ScreenTriangle& t, const TriangleBatch& batch, const ShadeContext& ctx, int y,
                int x0, int x1, Framebuffer& fb, Counters& c, std::uint64_t* newly_covered) {
  const RowShader rs(t, batch, ctx, y);
  std::size_t i = fb.index(x0, y);
  fb.ready_row(y);
  const float* depth = fb.depth_data();
  const std::uint32_t* ids = fb.ids_data();
  for (int x = x0; x <= x1; ++x, ++i) {
    const float z = rs.depth(x);
    if (!in_front(z, t.id, depth[i], ids[i])) continue;
    std::uint8_t rgb[3];
    rs.color(x, rgb, c);
    if (newly_covered) *newly_covered += ids[i] == kNoTriangle;
    fb.test_and_write(i, z, t.id, rgb);
    ++c.pixels_written;
  }
}

// The depth lines span [x0, x1] of row y enters in `recent`: those it did not hold (far_lines),
// and of them those outside the last-level-cache window too, added to `distant`.
std::uint64_t enter_lines(RecentLines* recent, const Framebuffer& fb, int y, int x0, int x1,
                          std::uint64_t& distant) {
  if (!recent) return 0;
  const std::size_t i = fb.index(x0, y);
  return recent->enter(i, i + std::size_t(x1 - x0), &distant);
}

void draw_untextured(const ScreenTriangle& t, const ShadeContext& ctx, const RowSet& rows,
                     Framebuffer& fb, Counters& c, std::uint64_t* newly_covered,
                     RecentLines* recent) {
  const FlatSpan s = flat(t, ctx, fb);
  std::uint64_t spans = 0, generated = 0, written = 0, first = 0, far = 0, distant = 0;
  for_each_span(t, rows, fb.width(), [&](int y, int x0, int x1) {
    ++spans;
    far += enter_lines(recent, fb, y, x0, x1, distant);
    flat_row(t, s, y, x0, x1, fb, written, first);
    generated += std::uint64_t(x1 - x0 + 1);
  });
  c.spans += spans;
  c.span_starts += spans; // each span's start values from its planes
  ++c.edge_walks;
  c.pixels_generated += generated;
  c.pixels_tested += generated;
  c.pixels_written += written;
  c.far_lines += far;
  c.distant_lines += distant;
  if (newly_covered) *newly_covered += first;
}

} // namespace

void draw_triangle(const ScreenTriangle& t, const TriangleBatch& batch, const ShadeContext& ctx,
                   const RowSet& rows, Framebuffer& fb, Counters& c, std::uint64_t* newly_covered,
                   RecentLines* recent) {
  if (t.tex < 0) {
    draw_untextured(t, ctx, rows, fb, c, newly_covered, recent);
    return;
  }
  ++c.edge_walks;
  for_each_span(t, rows, fb.width(), [&](int y, int x0, int x1) {
    ++c.spans;
    ++c.span_starts;
    c.far_lines += enter_lines(recent, fb, y, x0, x1, c.distant_lines);
    shaded_row(t, batch, ctx, y, x0, x1, fb, c, newly_covered);
    const std::uint64_t n = std::uint64_t(x1 - x0 + 1);
    c.pixels_generated += n;
    c.pixels_tested += n;
  });
}

void draw_span(const ScreenTriangle& t, const TriangleBatch& batch, const ShadeContext& ctx, int y,
               int x0, int x1, Framebuffer& fb, Counters& c) {
  ++c.span_starts;
  c.far_lines += enter_lines(&fb.recent_lines(), fb, y, x0, x1, c.distant_lines);
  const std::uint64_t n = std::uint64_t(x1 - x0 + 1);
  c.pixels_generated += n;
  c.pixels_tested += n;
  if (t.tex >= 0) {
    shaded_row(t, batch, ctx, y, x0, x1, fb, c, nullptr);
    return;
  }
  std::uint64_t written = 0, first = 0;
  flat_row(t, flat(t, ctx, fb), y, x0, x1, fb, written, first);
  c.pixels_written += written;
}

void draw_batch(const TriangleBatch& batch, const ShadeContext& ctx, Framebuffer& fb, Counters& c) {
  for (const auto& t : batch.tris)
    draw_triangle(t, batch, ctx, fb.rows(), fb, c, nullptr, &fb.recent_lines());
}

} // namespace zc
