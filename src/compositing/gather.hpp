#pragma once
// Paste (strips or slices to one node): the final pixels every node owns, gathered to one node
// and written into its picture without comparisons (the rows are disjoint). Kurc et al.'s output
// and the sort-last programs' (the records as the representation charges them).
#include <vector>

#include "comm/comm.hpp"
#include "compositing/records.hpp"
#include "raster/active_pixels.hpp"
#include "raster/framebuffer.hpp"
#include "util/counters.hpp"

namespace zc::compositing {

// The node's final pixels as one message (serialize_sparse), charged by `charge` (e.g.
// sparse_message, run_length_message); the copy into it counted into w.
Message pack_pixels(const ActivePixels& mine, Message (*charge)(Bytes, const PixelRecords&),
                    const PixelRecords& records, Counters& w);
// Every node's message to root, by rank there (coll::gatherv over the group's channels).
std::vector<Message> gather(Comm& c, int root, Message part);
// At root: every part written into `picture` (rows cleared by the caller), two passes over its
// bytes (the records unpacked, then written to their locations) counted into w. Returns the pixels
// written: the picture's covered pixels when the parts are every node's final pixels.
std::uint64_t paste(const std::vector<Message>& parts, Framebuffer& picture, int height,
                    Counters& w);

} // namespace zc::compositing
