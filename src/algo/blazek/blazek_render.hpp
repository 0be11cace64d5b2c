#pragma once
// Blazek 1991, ch. II "Z-buffer Rendering" (Algorithm 3): a node's projected polygons set up and
// scan-converted into its frame buffer (full, a strip, or interleaved rows).
#include <cstdint>
#include <vector>

#include "algo/algorithm.hpp"
#include "algo/blazek/blazek_mesh.hpp"
#include "raster/framebuffer.hpp"
#include "raster/renderer.hpp"

namespace zc::blazek {

// Sets up and scan-converts triangles of a projected mesh (all, or `subset`) into fb (on fb's
// rows); charges the work.
void render_mesh(NodeContext& ctx, const NodeRenderer& nr, const ProjectedMesh& pm, Framebuffer& fb,
                 const std::vector<std::uint32_t>* subset = nullptr);

} // namespace zc::blazek
