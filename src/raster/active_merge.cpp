// Merges of pixel sets (active_pixels.hpp): two sets, a set and a message still on the wire, many
// messages at once; and a set written into a frame buffer.
#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "raster/active_pixels.hpp"
#include "raster/active_wire.hpp"

namespace zc {

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
// merge_row with the second list still on the wire: each of its pixels decoded once, as reached.
void merge_row_wire(const WinningPixel* a, const WinningPixel* ae, const std::uint8_t* b,
                    const std::uint8_t* be, std::vector<WinningPixel>& out) {
  WinningPixel bp{};
  bool have = b < be;
  if (have) bp = active_wire::decode(b);
  const auto next_b = [&] {
    b += kWirePixelBytes;
    have = b < be;
    if (have) bp = active_wire::decode(b);
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

ActivePixels merge_sparse(const std::vector<const std::vector<std::uint8_t>*>& messages, int width,
                          int y0, int y1, std::vector<std::uint64_t>& pixel_counts) {
  struct Segment {
    int y;
    std::vector<WinningPixel> pixels;
  };
  std::vector<Segment> segments; // message by message, rows increasing within a message
  pixel_counts.assign(messages.size(), 0);
  for (std::size_t i = 0; i < messages.size(); ++i) {
    RecordReader in(*messages[i], active_wire::kWhat);
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
      active_wire::get_pixels(in, segments[s].pixels.data(), segments[s].pixels.size());
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
  RecordReader in(data, size, active_wire::kWhat);
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
