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

} // namespace zc::kurc
