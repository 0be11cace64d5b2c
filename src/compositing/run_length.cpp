// Run-length encoded active pixels (run_length.hpp): the same pixels and merges as the winning
// pixel array (winning_pixels.cpp), charged as IceT encodes them.
#include "compositing/run_length.hpp"

#include "compositing/winning_pixels.hpp"
#include "util/record_io.hpp"

namespace zc::compositing {

namespace {

std::size_t encoded(std::size_t runs, std::size_t pixels, const PixelRecords& r) {
  return (runs + 1) * 2 * r.count + pixels * r.location;
}

} // namespace

Message run_length_message(Bytes payload, const PixelRecords& records) {
  // serialize_sparse: u32 rows; (u32 y, u32 count) a row; then the pixels, x (u16) first.
  RecordReader in(payload, "run length");
  const std::uint32_t rows = payload.empty() ? 0 : in.get<std::uint32_t>();
  const auto heads = in.get_vector<std::uint32_t>(2 * std::size_t(rows));
  std::size_t runs = 0, pixels = 0;
  for (std::uint32_t i = 0; i < rows; ++i) {
    const std::uint32_t n = heads[2 * std::size_t(i) + 1];
    int last = -2;
    for (std::uint32_t k = 0; k < n; ++k) {
      const int x = in.get<std::uint16_t>();
      (void)in.get_bytes(kWirePixelBytes - sizeof(std::uint16_t)); // colour, depth, id
      runs += x != last + 1;
      last = x;
    }
    pixels += n;
  }
  const std::size_t charged = encoded(runs, pixels, records);
  return {std::move(payload), charged};
}

double run_length_bytes(const ActivePixels& a, const PixelRecords& records) {
  std::size_t runs = 0;
  for (int y = a.y0; y < a.y1; ++y) {
    int last = -2;
    for (std::uint32_t k = a.row_begin[y - a.y0]; k < a.row_begin[y - a.y0 + 1]; ++k) {
      runs += a.pixels[k].x != last + 1;
      last = a.pixels[k].x;
    }
  }
  return double(encoded(runs, a.count(), records));
}

std::unique_ptr<Picture> run_length(ActivePixels a, const PixelRecords& records) {
  return active_pixels(std::move(a), records, {"run-length", run_length_message, run_length_bytes});
}

} // namespace zc::compositing
