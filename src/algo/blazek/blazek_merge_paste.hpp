#pragma once
// Blazek 1991, ch. V: the end of every method. Host initiated and node initiated merge the nodes'
// full frame buffers hierarchically ("Host Initiated Method", Algorithm 4, Figure 10); object
// forwarding and host broadcast paste the nodes' strips or interleaved rows ("the partial node
// images are pasted together rather than merged").
#include "algo/algorithm.hpp"
#include "raster/framebuffer.hpp"

namespace zc::blazek {

// Algorithm 4 / Figure 10: log2 P steps; at step i the active nodes with bit i set send their
// frame buffer to the neighbour over channel i, which keeps the nearer pixel. Node 0 ends with
// the merged picture, which it delivers. Any P: a node whose partner would be P or above skips
// that step (a binomial tree).
void hierarchical_merge(NodeContext& ctx, Framebuffer fb);

// Strips or interleaved rows sent to node 0 (colour only, timed); each node hands over its rows,
// colour and depth, which make the picture.
void paste_at_node0(NodeContext& ctx, const Framebuffer& part);

} // namespace zc::blazek
