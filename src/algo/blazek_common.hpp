#pragma once
// Pieces shared by Blazek's four decompositions (thesis ch. V): what travels between the host
// (SRM) and the nodes, node-side tessellation and rendering, the hierarchical merge of Algorithm 4
// and the pasting of strips.
#include <functional>
#include <vector>

#include "algo/algorithm.hpp"
#include "raster/framebuffer.hpp"
#include "raster/renderer.hpp"
#include "scene/scene.hpp"

namespace zc::blazek {

// A polygon as the host sends it: its global id, material and world vertices (80 bytes).
struct Poly {
  std::uint32_t id, material;
  Vertex v[3];
};

constexpr int kTagHost = 1, kTagForward = 2, kTagMerge = 3;

// Checks the scene suits the methods (untextured; Blazek's renderer had no textures).
void check_scene(const Scene& s);

// Object description message: ranges + the one-line text (~100 bytes). Mesh objects, which no
// node can re-tessellate, travel as their polygons (kind "mesh" + a polygon payload).
Bytes encode_object(const Scene& s, std::size_t object);
// Decodes and tessellates (charging triangles_tessellated) into polygons.
std::vector<Poly> object_polygons(NodeContext& ctx, const Bytes& msg);
// The polygons of an object as the host tessellates them (charged to the caller).
std::vector<Poly> host_polygons(const Scene& s, std::size_t object, Counters& c);

// Projects, sets up and scan-converts polygons into fb (on fb's rows); charges the work.
void render_polygons(NodeContext& ctx, const NodeRenderer& nr, const std::vector<Poly>& polys,
                     Framebuffer& fb);

// Whether an object (its message) can touch any row of `rows`, judged from its description's
// bounding box alone (primitives fit [-1, 1]^3 before their transform). `triangles` receives its
// polygon count. Conservative: true when unsure (meshes, Bezier patches, near-plane crossings).
bool object_may_touch(const NodeRenderer& nr, const Bytes& msg, const RowSet& rows,
                      std::uint32_t& triangles);

// Rows [y0, y1] a polygon can touch (false: none).
bool polygon_rows(const NodeRenderer& nr, const Poly& p, int& y0, int& y1);

// The node side of host initiated and node initiated: a full frame buffer, every host message
// until the end marker turned into polygons by `polygons_of` and rendered, then the hierarchical
// merge.
void render_host_messages_then_merge(
    NodeContext& ctx, const std::function<std::vector<Poly>(const Bytes&)>& polygons_of);

// Algorithm 4 / Figure 10: log2 P steps; at step i the active nodes with bit i set send their
// frame buffer to the neighbour over channel i, which keeps the nearer pixel. Node 0 ends with
// the merged picture, which it delivers.
void hierarchical_merge(NodeContext& ctx, Framebuffer fb);

// Strips or interleaved rows pasted at node 0 (colour only), which delivers the picture.
void paste_at_node0(NodeContext& ctx, const NodeRenderer& nr, const Framebuffer& part);

// The host's end-of-work marker: an empty message.
inline bool is_end(const Bytes& b) {
  return b.empty();
}

} // namespace zc::blazek
