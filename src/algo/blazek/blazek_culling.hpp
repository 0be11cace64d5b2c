#pragma once
// Blazek 1991, ch. V "Node Initiated with Object Forwarding Method" and "Host Broadcast Method":
// the frame buffer decomposed into strips (or interleaved scan-lines), and the tests of what can
// land in a node's rows ("Polygons lying wholly outside of the node's portion of the frame buffer
// are discarded").
#include <cstdint>
#include <vector>

#include "algo/algorithm.hpp"
#include "algo/blazek/blazek_mesh.hpp"
#include "raster/renderer.hpp"
#include "util/block_split.hpp"

namespace zc::blazek {

// Whether an object (its message) can touch any row of `rows`, judged from its description's
// bounding box alone (primitives fit [-1, 1]^3 before their transform). `triangles` receives its
// polygon count. Conservative: true when unsure (meshes, Bezier patches, near-plane crossings).
bool object_may_touch(const NodeRenderer& nr, const Bytes& msg, const RowSet& rows,
                      std::uint32_t& triangles);

// The triangles of a projected mesh that can touch `rows` (charges triangles_estimated: the test
// the strip methods make for every polygon).
std::vector<std::uint32_t> triangles_touching(NodeContext& ctx, const NodeRenderer& nr,
                                              const ProjectedMesh& pm, const RowSet& rows);

// The strip methods' decomposition ("each strip is X/P pixels in height"): node k of P owns the
// block of rows [kH/P, (k+1)H/P) (some strips are empty when P > H), and row y lies in the strip
// whose block holds it (util/block_split.hpp).
inline RowSet strip_rows(int k, int P, int H) {
  const BlockRange b = block_range(std::size_t(H), P, k);
  return RowSet::band(int(b.begin), int(b.end));
}
inline int strip_of_row(int y, int P, int H) {
  return block_of(std::size_t(H), P, std::size_t(y));
}

} // namespace zc::blazek
