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
// Pixel by pixel, a written pixel's colour (clamps and conversions) took about 63 instructions,
// two thirds of an appended pixel's; the frame buffer's loop, on which the probe prices a written
// pixel, spends 11.
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

namespace {
// One row of merge_active: two x-sorted lists, the nearer pixel (depth, then lower id) winning at
// equal x.
void merge_row(const WinningPixel* a, const WinningPixel* ae, const WinningPixel* b,
               const WinningPixel* be, std::vector<WinningPixel>& out) {
  while (a < ae || b < be) {
    if (b == be || (a < ae && a->x < b->x)) {
      out.push_back(*a++);
    } else if (a == ae || b->x < a->x) {
      out.push_back(*b++);
    } else {
      out.push_back(in_front(b->z, b->id, a->z, a->id) ? *b : *a);
      ++a;
      ++b;
    }
  }
}
} // namespace

ActivePixels merge_active(const ActivePixels& a, const ActivePixels& b, Counters& c) {
  if (a.y0 != b.y0 || a.y1 != b.y1 || a.width != b.width)
    throw std::logic_error("merge_active: pixel sets cover different rows");
  ActivePixels r;
  r.width = a.width;
  r.y0 = a.y0;
  r.y1 = a.y1;
  r.row_begin.assign(a.row_begin.size(), 0);
  r.pixels.reserve(a.pixels.size() + b.pixels.size());
  for (int y = a.y0; y < a.y1; ++y) {
    const std::size_t k = std::size_t(y - a.y0);
    merge_row(a.pixels.data() + a.row_begin[k], a.pixels.data() + a.row_begin[k + 1],
              b.pixels.data() + b.row_begin[k], b.pixels.data() + b.row_begin[k + 1], r.pixels);
    r.row_begin[k + 1] = std::uint32_t(r.pixels.size());
  }
  c.list_merges += a.pixels.size() + b.pixels.size();
  return r;
}

void scatter_active(const ActivePixels& a, Framebuffer& fb) {
  for (int y = a.y0; y < a.y1; ++y)
    for (std::uint32_t k = a.row_begin[y - a.y0]; k < a.row_begin[y - a.y0 + 1]; ++k) {
      const WinningPixel& p = a.pixels[k];
      const std::size_t i = fb.index(p.x, y);
      fb.depth()[i] = p.z;
      fb.ids()[i] = p.id;
      std::memcpy(&fb.rgb()[3 * i], p.rgb, 3);
    }
}

namespace {
constexpr const char* kWhat = "active pixels";
// One pixel on the wire: x(2) rgb(3) z(4) id(4) = kWirePixelBytes.
void encode(std::uint8_t* q, const WinningPixel& p) {
  std::memcpy(q, &p.x, 2);
  std::memcpy(q + 2, p.rgb, 3);
  std::memcpy(q + 5, &p.z, 4);
  std::memcpy(q + 9, &p.id, 4);
}
WinningPixel decode(const std::uint8_t* q) {
  WinningPixel px;
  std::memcpy(&px.x, q, 2);
  std::memcpy(px.rgb, q + 2, 3);
  std::memcpy(&px.z, q + 5, 4);
  std::memcpy(&px.id, q + 9, 4);
  return px;
}
// n pixels appended to `out` (its capacity reserved before: nothing cleared, then overwritten),
// encoded a block at a time into the stack (a bounds check a field made a message of winning
// pixels cost 60 instructions a pixel).
void append_pixels(std::vector<std::uint8_t>& out, const WinningPixel* p, std::size_t n) {
  constexpr std::size_t kBlock = 256;
  std::uint8_t buf[kBlock * kWirePixelBytes];
  while (n) {
    const std::size_t k = std::min(n, kBlock);
    for (std::size_t i = 0; i < k; ++i)
      encode(buf + i * kWirePixelBytes, p[i]);
    out.insert(out.end(), buf, buf + k * kWirePixelBytes);
    p += k;
    n -= k;
  }
}
void append_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  std::uint8_t b[4];
  std::memcpy(b, &v, 4);
  out.insert(out.end(), b, b + 4);
}
// n pixels read in place after one bounds check.
void get_pixels(RecordReader& in, WinningPixel* out, std::size_t n) {
  const std::uint8_t* q = in.get_bytes(n * kWirePixelBytes);
  for (std::size_t i = 0; i < n; ++i)
    out[i] = decode(q + i * kWirePixelBytes);
}
// merge_row with the second list still on the wire: each of its pixels decoded once, as reached.
void merge_row_wire(const WinningPixel* a, const WinningPixel* ae, const std::uint8_t* b,
                    const std::uint8_t* be, std::vector<WinningPixel>& out) {
  WinningPixel bp{};
  bool have = b < be;
  if (have) bp = decode(b);
  const auto next_b = [&] {
    b += kWirePixelBytes;
    have = b < be;
    if (have) bp = decode(b);
  };
  while (a < ae || have) {
    if (!have || (a < ae && a->x < bp.x)) {
      out.push_back(*a++);
    } else if (a == ae || bp.x < a->x) {
      out.push_back(bp);
      next_b();
    } else {
      out.push_back(in_front(bp.z, bp.id, a->z, a->id) ? bp : *a);
      ++a;
      next_b();
    }
  }
}
} // namespace

// Layout: u32 row count; per non-empty row (u32 y, u32 count); then per pixel x(2) rgb(3) z(4)
// id(4).
std::vector<std::uint8_t> serialize_sparse(const ActivePixels& a) {
  // Every row to one destination: appended into its reserved buffer (serialize_sparse_by_owner),
  // not sized (a clear of the whole message) and then overwritten.
  return std::move(
      serialize_sparse_by_owner(a, std::vector<int>(std::size_t(std::max(a.y1, 0)), 0), 1)[0]);
}

ActivePixels deserialize_sparse(const std::uint8_t* p, std::size_t size, int width, int y0,
                                int y1) {
  RecordReader in(p, size, kWhat);
  ActivePixels a;
  a.width = width;
  a.y0 = y0;
  a.y1 = y1;
  a.row_begin.assign(std::size_t(y1 - y0) + 1, 0);
  const std::uint32_t rows = in.get<std::uint32_t>();
  std::vector<std::uint32_t> count(std::size_t(y1 - y0), 0);
  int last = y0 - 1;
  for (std::uint32_t i = 0; i < rows; ++i) {
    const int y = int(in.get<std::uint32_t>());
    if (y < y0 || y >= y1 || y <= last) throw std::runtime_error("active pixels: bad row");
    count[y - y0] = in.get<std::uint32_t>();
    last = y;
  }
  for (int y = y0; y < y1; ++y)
    a.row_begin[y - y0 + 1] = a.row_begin[y - y0] + count[y - y0];
  in.require(a.row_begin.back(), kWirePixelBytes);
  // Decoded into the reserved array (sized first, it would be cleared, then overwritten).
  const std::size_t n = a.row_begin.back();
  const std::uint8_t* q = in.get_bytes(n * kWirePixelBytes);
  a.pixels.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    a.pixels.push_back(decode(q + i * kWirePixelBytes));
  return a;
}

} // namespace zc

namespace zc {

std::vector<std::vector<std::uint8_t>>
serialize_sparse_by_owner(const ActivePixels& a, const std::vector<int>& owner, int parts) {
  std::vector<std::uint32_t> rows(std::size_t(parts), 0);
  std::vector<std::size_t> pixels(std::size_t(parts), 0);
  const auto dest = [&](int y) { // rows owned by no destination are not sent (as select_rows)
    const int k = owner[std::size_t(y)];
    return k >= 0 && k < parts ? k : -1;
  };
  for (int y = a.y0; y < a.y1; ++y)
    if (const std::uint32_t n = a.row_count(y); n && dest(y) >= 0) {
      ++rows[std::size_t(dest(y))];
      pixels[std::size_t(dest(y))] += n;
    }
  // Each part appended into its reserved buffer, its row headers and then its pixels (as
  // serialize_sparse lays them out): a message of a pair's exchange is tens of megabytes, which a
  // buffer sized first would clear only to overwrite.
  std::vector<std::vector<std::uint8_t>> out(static_cast<std::size_t>(parts));
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].reserve(4 + 8 * std::size_t(rows[k]) + kWirePixelBytes * pixels[k]);
    append_u32(out[k], rows[k]);
  }
  for (int y = a.y0; y < a.y1; ++y)
    if (const std::uint32_t n = a.row_count(y); n && dest(y) >= 0) {
      append_u32(out[std::size_t(dest(y))], std::uint32_t(y));
      append_u32(out[std::size_t(dest(y))], n);
    }
  for (int y = a.y0; y < a.y1; ++y)
    if (const std::uint32_t n = a.row_count(y); n && dest(y) >= 0)
      append_pixels(out[std::size_t(dest(y))], a.pixels.data() + a.row_begin[std::size_t(y - a.y0)],
                    n);
  return out;
}

ActivePixels merge_sparse(const std::vector<const std::vector<std::uint8_t>*>& messages, int width,
                          int y0, int y1, std::vector<std::uint64_t>& pixel_counts) {
  struct Segment {
    int y;
    std::vector<WinningPixel> pixels;
  };
  std::vector<Segment> segments; // message by message, rows increasing within a message
  pixel_counts.assign(messages.size(), 0);
  for (std::size_t i = 0; i < messages.size(); ++i) {
    RecordReader in(*messages[i], kWhat);
    const std::uint32_t rows = in.get<std::uint32_t>();
    const std::size_t first = segments.size();
    int last = y0 - 1;
    for (std::uint32_t r = 0; r < rows; ++r) {
      const int y = int(in.get<std::uint32_t>());
      if (y < y0 || y >= y1 || y <= last) throw std::runtime_error("active pixels: bad row");
      const std::uint32_t n = in.get<std::uint32_t>();
      in.require(n, kWirePixelBytes);
      segments.push_back({y, std::vector<WinningPixel>(n)});
      last = y;
    }
    for (std::size_t s = first; s < segments.size(); ++s) {
      get_pixels(in, segments[s].pixels.data(), segments[s].pixels.size());
      pixel_counts[i] += segments[s].pixels.size();
    }
  }
  // Rows in order, each row's messages in the order given (a stable sort keeps it).
  std::stable_sort(segments.begin(), segments.end(),
                   [](const Segment& a, const Segment& b) { return a.y < b.y; });
  ActivePixels r;
  r.width = width;
  r.y0 = y0;
  r.y1 = y1;
  r.row_begin.assign(std::size_t(y1 - y0) + 1, 0);
  std::vector<WinningPixel> row, merged;
  int next = y0; // rows before `next` have their row_begin set
  for (std::size_t s = 0; s < segments.size();) {
    const int y = segments[s].y;
    row.clear();
    for (; s < segments.size() && segments[s].y == y; ++s) {
      merged.clear();
      const auto& seg = segments[s].pixels;
      merge_row(row.data(), row.data() + row.size(), seg.data(), seg.data() + seg.size(), merged);
      row.swap(merged);
    }
    for (; next <= y; ++next)
      r.row_begin[std::size_t(next - y0)] = std::uint32_t(r.pixels.size());
    r.pixels.insert(r.pixels.end(), row.begin(), row.end());
  }
  for (; next <= y1; ++next)
    r.row_begin[std::size_t(next - y0)] = std::uint32_t(r.pixels.size());
  return r;
}

ActivePixels merge_active_sparse(const ActivePixels& a, const std::uint8_t* data, std::size_t size,
                                 Counters& c, std::uint64_t& received) {
  RecordReader in(data, size, kWhat);
  const std::uint32_t rows = in.get<std::uint32_t>();
  in.require(rows, 8);
  std::vector<std::pair<int, std::uint32_t>> heads(rows);
  std::size_t total = 0;
  int last = a.y0 - 1;
  for (auto& [y, n] : heads) {
    y = int(in.get<std::uint32_t>());
    if (y < a.y0 || y >= a.y1 || y <= last) throw std::runtime_error("active pixels: bad row");
    n = in.get<std::uint32_t>();
    total += n;
    last = y;
  }
  in.require(total, kWirePixelBytes);
  const std::uint8_t* q = in.get_bytes(total * kWirePixelBytes);
  ActivePixels r;
  r.width = a.width;
  r.y0 = a.y0;
  r.y1 = a.y1;
  r.row_begin.assign(a.row_begin.size(), 0);
  r.pixels.reserve(a.pixels.size() + total);
  std::size_t h = 0;
  for (int y = a.y0; y < a.y1; ++y) {
    const std::size_t k = std::size_t(y - a.y0);
    const std::size_t n = h < heads.size() && heads[h].first == y ? heads[h++].second : 0;
    merge_row_wire(a.pixels.data() + a.row_begin[k], a.pixels.data() + a.row_begin[k + 1], q,
                   q + n * kWirePixelBytes, r.pixels);
    q += n * kWirePixelBytes;
    r.row_begin[k + 1] = std::uint32_t(r.pixels.size());
  }
  c.list_merges += a.pixels.size() + total;
  received = total;
  return r;
}

} // namespace zc
