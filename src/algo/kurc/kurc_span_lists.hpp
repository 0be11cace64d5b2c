#pragma once
// Kurc, Aykanat, Ozguc: the steps every merge scheme shares before the local z-buffer. The
// triangles are dealt round-robin to the nodes (distribute), then each node projects and sets up
// its triangles and buckets their spans into x_min-sorted scanline lists (span list creation, §2
// first step).
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "algo/algorithm.hpp"
#include "algo/world_polygon.hpp"
#include "raster/active_pixels.hpp"
#include "raster/renderer.hpp"

namespace zc::kurc {

// A triangle dealt to a node: the world polygon record and its vertex ids, so that shared
// vertices are transformed once per node.
struct TriWorld {
  WorldPolygon poly;
  std::uint32_t vid[3];
};
struct TriUV {
  glm::vec2 uv[3];
};

// A node's share of the scene: triangle i of the scene goes to node i mod P.
struct NodeTriangles {
  std::vector<TriWorld> tris;
  std::vector<TriUV> uvs; // per triangle, textured scenes only
};

// Distribute: node 0 reads the scene and deals the triangles with their world vertices.
NodeTriangles distribute_triangles(NodeContext& ctx);
// Every triangle of the scene as one node holds it (the one-node reference: no distribute).
NodeTriangles all_triangles(const Scene& scene);

// The span lists of a node's triangles and the screen triangles they index.
struct NodeSpans {
  TriangleBatch batch;
  SpanLists lists;
  double bytes() const {
    return double(lists.bytes() + batch.tris.size() * sizeof(ScreenTriangle));
  }
};

// Span list creation (§2, first step).
NodeSpans create_span_lists(NodeContext& ctx, const NodeRenderer& nr, const NodeTriangles& mine);

// The modified scanline z-buffer (§2, second step): the spans through the MSA (a scanline of
// depths, a C int a column) into the Winning Pixel Array, both held in node memory (the WPA as
// the paper's records: a WPA entry a pixel, a count a scanline); work into w.
ActivePixels scanline_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans,
                              Counters& w);

} // namespace zc::kurc
