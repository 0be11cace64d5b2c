#pragma once
// Blazek 1991, ch. V: what a node does with the host's messages in the three methods that deal the
// object set ("Host Initiated Method", "Node Initiated Method", "Node Initiated with Object
// Forwarding Method"): it receives packets or descriptions "in a round-robin fashion" until the
// host's end marker, holding each in its memory while it renders it.
#include <functional>

#include "algo/algorithm.hpp"
#include "raster/framebuffer.hpp"
#include "raster/renderer.hpp"

namespace zc::blazek {

// A full frame buffer ("an entire frame buffer was maintained on each node"), allocated in node
// memory and cleared (pixels_cleared charged to the current phase).
Framebuffer full_frame_buffer(NodeContext& ctx, const NodeRenderer& nr);

// Every message from the host until its end marker, each held in node memory ("host message")
// while `render` uses it.
void for_each_host_message(NodeContext& ctx, const std::function<void(const Message&)>& render);

} // namespace zc::blazek
