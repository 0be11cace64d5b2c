#pragma once
// Charles, Lefevre, Miguet 1995, §4: the steps of the parallel z-buffer that do not depend on how
// the projected vertices travel, one function per step of the paper's listing. The node program
// (elastic.cpp) calls them in the paper's order; each step is one report phase.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "algo/algorithm.hpp"
#include "algo/charles/elastic_partition.hpp"
#include "raster/renderer.hpp"
#include "util/block_split.hpp"

namespace zc::elastic {

// What a node holds for the whole animation once the scene is scattered.
struct LocalScene {
  std::size_t first_vertex = 0;          // global id of vertices[0]
  std::size_t scene_vertices = 0;        // V, the scene's vertex count
  std::size_t scene_triangles = 0;       // T, the scene's triangle count
  std::vector<Vertex> vertices;          // this node's block of vertices
  std::vector<TriangleRecord> triangles; // this node's block of triangles
  std::vector<glm::vec2> uvs;            // every texture coordinate (textured scenes only)
};

// Scatter(Vertices); Scatter(Triangles): equal contiguous blocks from node 0. Texture coordinates
// do not change with the camera: they are multi-broadcast once, when the scene is textured.
LocalScene scatter_scene(NodeContext& ctx);

// LocalLoad = Estimation(local triangles) is in elastic.cpp: it reads the projected vertices.
struct LocalLoad {
  std::vector<RowExtent> extents; // rows each local triangle covers ({1, 0}: none)
  std::vector<std::int64_t> rows; // estimated load (triangles) per picture row
};

// GlobalLoad = MultiReduce(LocalLoad).
std::vector<std::int64_t> multireduce_load(NodeContext& ctx,
                                           const std::vector<std::int64_t>& local);

// The elastic cut of the rows into P slices of equal estimated work (§5): P+1 row boundaries.
std::vector<int> partition_rows(NodeContext& ctx, const std::vector<std::int64_t>& global_load);

// Visits, in order, the non-empty slices k (rows [bounds[k], bounds[k+1])) that rows e touch.
template <class Visit>
void for_each_slice(const std::vector<int>& bounds, const RowExtent& e, Visit&& visit) {
  if (e.y0 > e.y1) return;
  const int P = int(bounds.size()) - 1;
  int k = int(std::upper_bound(bounds.begin(), bounds.end(), e.y0) - bounds.begin()) - 1;
  for (; k < P && bounds[k] <= e.y1; ++k)
    if (bounds[k] != bounds[k + 1]) visit(k);
}

// What the output step reports for one node's slice (Table 1 of the paper).
struct SliceOutput {
  int frame = 0;
  bool last_frame = false;
  bool gather = false;       // --output gather: node 0 assembles the picture
  std::size_t triangles = 0; // triangles rendered in the slice, duplicates included
  std::size_t scene_triangles = 0;
};

// Output the picture (§4 "write the image to an output device"). --output device: each node
// writes its slice to the device itself, so the communication volume does not depend on the
// resolution (§6); --output gather: slices gathered to node 0 (colour only), which then holds the
// picture (the slices, colour and depth, make the picture of the report). Node 0 also records Table
// 1 (per node triangles, workload, rows) after the last frame.
void output_picture(NodeContext& ctx, Framebuffer slice,
                    const std::vector<std::int64_t>& global_load, const SliceOutput& out);

} // namespace zc::elastic
