#pragma once
// IceT's run-length encoded active pixels (IceT src/ice-t/image.c: a run is a pair of 32-bit
// counts, inactive then active pixels, followed by the active pixels' colour and depth), as a
// compositing representation: no pixel carries its x, a row's pixels cost a run header per run of
// consecutive columns instead. docs/compositing.md, "Records", derives the sizes.
#include <memory>

#include "compositing/picture.hpp"
#include "compositing/records.hpp"

namespace zc::compositing {

// A serialize_sparse payload charged as run-length encoded: 2 x records.count a run (plus the
// closing inactive run) and records.location a pixel (z and colour, no x).
Message run_length_message(Bytes payload, const PixelRecords& records);
double run_length_bytes(const ActivePixels& a, const PixelRecords& records);

std::unique_ptr<Picture> run_length(ActivePixels a, const PixelRecords& records);

} // namespace zc::compositing
