#include "raster/active_pixels.hpp"
#include "raster/recent_records.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "raster/avx2_lanes.hpp"
#include "raster/zbuffer.hpp"
#include "util/record_io.hpp"

namespace zc {

namespace {
// The columns an x_min-sorted scanline list covers: what zbuffer_spans appends to the WPA (each
// span's columns right of those produced before it).
std::size_t union_columns(std::vector<SpanRecord>::const_iterator b,
                          std::vector<SpanRecord>::const_iterator e) {
  std::size_t n = 0;
  int maxx = -1;
  for (; b != e; ++b) {
    const int from = std::max(b->x0, maxx + 1);
    if (b->x1 >= from) n += std::size_t(b->x1 - from + 1);
    maxx = std::max(maxx, b->x1);
  }
  return n;
}
} // namespace

namespace {
#ifdef ZC_HAVE_AVX2_LANES
bool has_avx2() {
  return avx2::available();
}

// The untextured pixels [x0, x1] of a row appended to the WPA eight at a time, bit for bit what
// RowShader's depth and color give (raster/avx2_lanes.hpp, as the frame buffer's span loop).
// Pixel by pixel, a written pixel's colour (clamps and conversions) is most of an appended
// pixel's work and several times what the frame buffer's vector loop spends on it; the probe
// prices a written pixel on that loop, so both loops colour alike.
__attribute__((target("avx2"))) void append_flat_avx2(const RowShader& rs, int x0, int x1,
                                                      std::vector<WinningPixel>& wpa,
                                                      std::uint32_t* msa) {
  const ScreenTriangle& t = *rs.t;
  const __m256d zax = _mm256_set1_pd(t.z.ax), rax = _mm256_set1_pd(t.r.ax);
  const __m256d gax = _mm256_set1_pd(t.g.ax), bax = _mm256_set1_pd(t.b.ax);
  const __m256 kr = _mm256_set1_ps(rs.kd.x), kg = _mm256_set1_ps(rs.kd.y);
  const __m256 kb = _mm256_set1_ps(rs.kd.z);
  alignas(32) float z[8];
  alignas(32) std::int32_t r[8], g[8], b[8];
  for (int x = x0; x <= x1; x += 8) {
    const avx2::Columns xs = avx2::columns8(x);
    _mm256_store_ps(z, avx2::plane8(rs.z0, zax, xs));
    _mm256_store_si256(reinterpret_cast<__m256i*>(r),
                       avx2::to_bytes8(_mm256_mul_ps(avx2::plane8(rs.r0, rax, xs), kr)));
    _mm256_store_si256(reinterpret_cast<__m256i*>(g),
                       avx2::to_bytes8(_mm256_mul_ps(avx2::plane8(rs.g0, gax, xs), kg)));
    _mm256_store_si256(reinterpret_cast<__m256i*>(b),
                       avx2::to_bytes8(_mm256_mul_ps(avx2::plane8(rs.b0, bax, xs), kb)));
    const int n = std::min(8, x1 - x + 1);
    for (int k = 0; k < n; ++k) {
      wpa.push_back({z[k],
                     t.id,
                     std::uint16_t(x + k),
                     {std::uint8_t(r[k]), std::uint8_t(g[k]), std::uint8_t(b[k])}});
      msa[x + k] = std::uint32_t(wpa.size());
    }
  }
}
#else
bool has_avx2() {
  return false;
}
void append_flat_avx2(const RowShader&, int, int, std::vector<WinningPixel>&, std::uint32_t*) {}
#endif
} // namespace

SpanLists build_span_lists(const TriangleBatch& batch, int width, int height, Counters& c) {
  SpanLists L;
  L.height = height;
  L.row_begin.assign(std::size_t(height) + 1, 0);
  // Two passes (count, then fill) give every scanline's list one contiguous block.
  std::vector<std::uint32_t> count(height, 0);
  for (const auto& t : batch.tris)
    for_each_span(t, RowSet::all(height), width, [&](int y, int, int) { ++count[y]; });
  for (int y = 0; y < height; ++y)
    L.row_begin[y + 1] = L.row_begin[y] + count[y];
  L.spans.resize(L.row_begin[height]);
  std::vector<std::uint32_t> fill(L.row_begin.begin(), L.row_begin.end() - 1);
  for (std::uint32_t i = 0; i < batch.tris.size(); ++i)
    for_each_span(batch.tris[i], RowSet::all(height), width, [&](int y, int x0, int x1) {
      L.spans[fill[y]++] = SpanRecord{x0, x1, i};
    });
  c.spans += L.spans.size();
  c.edge_walks += 2 * batch.tris.size(); // two passes over every triangle's rows
  for (int y = 0; y < height; ++y) {
    auto b = L.spans.begin() + L.row_begin[y], e = L.spans.begin() + L.row_begin[y + 1];
    c.sort_steps += sort_steps(std::uint64_t(e - b));
    std::stable_sort(b, e, [&](const SpanRecord& p, const SpanRecord& q) {
      if (p.x0 != q.x0) return p.x0 < q.x0;
      return batch.tris[p.tri].id < batch.tris[q.tri].id;
    });
    L.covered += union_columns(b, e);
  }
  return L;
}

ActivePixels zbuffer_spans(const SpanLists& L, const TriangleBatch& batch, const ShadeContext& ctx,
                           int width, Counters& c) {
  ActivePixels A;
  A.width = width;
  A.y0 = 0;
  A.y1 = L.height;
  A.row_begin.assign(std::size_t(L.height) + 1, 0);
  A.pixels.reserve(L.covered);
  // MSA[x] = 1 + index in the WPA of the pixel at column x; valid only if >= range (§2).
  std::vector<std::uint32_t> msa(width, 0);
  RecentRecords records; // the set-up records read last (a fetch from memory on a host)
  records.reset(batch.tris.size());
  for (int y = 0; y < L.height; ++y) {
    const std::uint32_t range = std::uint32_t(A.pixels.size()) + 1;
    int maxx = -1; // rightmost column produced so far on this scanline
    for (std::uint32_t s = L.row_begin[y]; s < L.row_begin[y + 1]; ++s) {
      const SpanRecord& sp = L.spans[s];
      const ScreenTriangle& t = batch.tris[sp.tri];
      const RowShader rs(t, batch, ctx, y);
      c.records_fetched += records.read(sp.tri);
      ++c.span_starts;
      c.pixels_generated += std::uint64_t(sp.x1 - sp.x0 + 1);
      // First segment: columns already produced on this scanline (contiguous, since spans come
      // sorted by x_min): depth comparisons.
      const int seg_end = std::min(sp.x1, maxx);
      for (int x = sp.x0; x <= seg_end; ++x) {
        WinningPixel& w = A.pixels[msa[x] - 1];
        const float z = rs.depth(x);
        ++c.wpa_tested;
        if (in_front(z, t.id, w.z, w.id)) {
          w.z = z;
          w.id = t.id;
          rs.color(x, w.rgb, c);
          ++c.pixels_written;
        }
      }
      // Second segment: new columns, appended to the WPA without comparison.
      int x = std::max(sp.x0, maxx + 1);
      if (t.tex < 0 && sp.x1 - x >= 1 && has_avx2()) { // one pixel: the scalar loop (flat_row)
        append_flat_avx2(rs, x, sp.x1, A.pixels, msa.data());
        c.wpa_appended += std::uint64_t(sp.x1 - x + 1);
        c.pixels_written += std::uint64_t(sp.x1 - x + 1);
        x = sp.x1 + 1;
      }
      for (; x <= sp.x1; ++x) {
        WinningPixel w;
        w.z = rs.depth(x);
        w.id = t.id;
        w.x = std::uint16_t(x);
        rs.color(x, w.rgb, c);
        A.pixels.push_back(w);
        msa[x] = std::uint32_t(A.pixels.size()); // >= range by construction
        ++c.wpa_appended;
        ++c.pixels_written;
      }
      maxx = std::max(maxx, sp.x1);
    }
    (void)range; // the range test is implied by the segment split (see header)
    A.row_begin[y + 1] = std::uint32_t(A.pixels.size());
  }
  return A;
}

} // namespace zc
