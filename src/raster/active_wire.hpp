#pragma once
// One winning pixel on the wire (active_pixels.hpp's sparse format), shared by the writer and
// reader of that format (active_wire.cpp) and the merges that read it in place (active_merge.cpp).
#include <cstdint>
#include <cstring>

#include "raster/active_pixels.hpp"
#include "util/record_io.hpp"

namespace zc::active_wire {

constexpr const char* kWhat = "active pixels";
// One pixel on the wire: x(2) rgb(3) z(4) id(4) = kWirePixelBytes.
inline void encode(std::uint8_t* q, const WinningPixel& p) {
  std::memcpy(q, &p.x, 2);
  std::memcpy(q + 2, p.rgb, 3);
  std::memcpy(q + 5, &p.z, 4);
  std::memcpy(q + 9, &p.id, 4);
}
inline WinningPixel decode(const std::uint8_t* q) {
  WinningPixel px;
  std::memcpy(&px.x, q, 2);
  std::memcpy(px.rgb, q + 2, 3);
  std::memcpy(&px.z, q + 5, 4);
  std::memcpy(&px.id, q + 9, 4);
  return px;
}
// n pixels read in place after one bounds check.
inline void get_pixels(RecordReader& in, WinningPixel* out, std::size_t n) {
  const std::uint8_t* q = in.get_bytes(n * kWirePixelBytes);
  for (std::size_t i = 0; i < n; ++i)
    out[i] = decode(q + i * kWirePixelBytes);
}

} // namespace zc::active_wire
