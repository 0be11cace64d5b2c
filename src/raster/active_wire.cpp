// The sparse wire format of pixel sets (active_pixels.hpp): written and read.
#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "raster/active_pixels.hpp"
#include "raster/active_wire.hpp"

namespace zc {

namespace {
// n pixels appended to `out` (its capacity reserved before: nothing cleared, then overwritten),
// encoded a block at a time into the stack (a bounds check a field would cost a message of winning
// pixels far more than its bytes' copy, work the paper's program, which sent its WPA in place,
// never did).
void append_pixels(std::vector<std::uint8_t>& out, const WinningPixel* p, std::size_t n) {
  constexpr std::size_t kBlock = 256;
  std::uint8_t buf[kBlock * kWirePixelBytes];
  while (n) {
    const std::size_t k = std::min(n, kBlock);
    for (std::size_t i = 0; i < k; ++i)
      active_wire::encode(buf + i * kWirePixelBytes, p[i]);
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
  RecordReader in(p, size, active_wire::kWhat);
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
    a.pixels.push_back(active_wire::decode(q + i * kWirePixelBytes));
  return a;
}

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

} // namespace zc
