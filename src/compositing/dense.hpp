#pragma once
// The dense representation: a full-screen z-buffer (depth and colour at every location, covered or
// not), as Kurc et al.'s ZBUF-EXC and Blazek's merge hold it. Every location of the rows routed
// travels and is compared, covered or not.
#include <memory>

#include "compositing/picture.hpp"
#include "compositing/records.hpp"
#include "raster/framebuffer.hpp"

namespace zc::compositing {

// `full`: the node's z-buffer over every row of the screen (its memory the caller's).
std::unique_ptr<Picture> dense(Framebuffer full, const PixelRecords& records);
// The z-buffer a dense picture holds (the whole screen; its rows not held are stale): for a
// strategy that ends at one node (tree), the merged picture itself.
Framebuffer& framebuffer(Picture& dense_picture);

} // namespace zc::compositing
