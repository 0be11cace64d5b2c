#pragma once
// Blazek 1991, ch. V "Node Initiated with Object Forwarding Method" and "Host Broadcast Method":
// the frame buffer decomposed into strips (or interleaved scan-lines), and the tests of what can
// land in a node's rows ("Polygons lying wholly outside of the node's portion of the frame buffer
// are discarded").
#include <cstdint>
#include <vector>

#include "algo/algorithm.hpp"
#include "algo/blazek_mesh.hpp"
#include "raster/renderer.hpp"

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

// The strip methods' decomposition: node k of P owns rows [kH/P, (k+1)H/P) (some strips are empty
// when P > H), and row y lies in strip ((y+1)P - 1) / H, the last strip starting at or before y
// (yP/H is not: with H = 77 and P = 2, row 38 starts strip 1 but 38*2/77 = 0).
inline RowSet strip_rows(int k, int P, int H) {
  return RowSet::band(int(std::int64_t(k) * H / P), int(std::int64_t(k + 1) * H / P));
}
inline int strip_of_row(int y, int P, int H) {
  return int(((std::int64_t(y) + 1) * P - 1) / H);
}

} // namespace zc::blazek
