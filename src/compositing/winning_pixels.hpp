#pragma once
// Kurc, Aykanat, Ozguc's winning pixel array (§2) as a compositing representation: each row's
// active pixels consecutive and sorted by x; only the non-empty rows travel, as (row, count)
// pairs and pixel records (raster/active_pixels.hpp's sparse format).
#include <memory>

#include "compositing/picture.hpp"
#include "compositing/records.hpp"

namespace zc::compositing {

// A sparse pixel message (serialize_sparse) as the modelled program sends it: its row counts and
// each pixel charged as records.pixel instead of zcube's kWirePixelBytes.
Message sparse_message(Bytes payload, const PixelRecords& records);
// The pixels as the modelled node holds them: a record a pixel and a count a row.
double held_bytes(const ActivePixels& a, const PixelRecords& records);

// `wpa`: the node's local foremost pixels over every row of the screen, already charged to its
// memory as held_bytes.
std::unique_ptr<Picture> winning_pixels(ActivePixels wpa, const PixelRecords& records);

// How a representation of active pixels is charged: a message of serialize_sparse's payload, and
// a set of pixels held. The winning pixel array (above) and run-length encoding (run_length.hpp)
// hold and merge the same pixels, and differ in these.
struct Encoding {
  const char* name;
  Message (*message)(Bytes payload, const PixelRecords& records);
  double (*held)(const ActivePixels& a, const PixelRecords& records);
};
std::unique_ptr<Picture> active_pixels(ActivePixels a, const PixelRecords& records,
                                       const Encoding& encoding);

} // namespace zc::compositing
