// Blazek 1991, ch. V "Host Broadcast Method": "Polygons lying wholly outside of the node's portion
// of the frame buffer are discarded", judged for a whole object from its description, or polygon
// by polygon (blazek_culling.hpp).
#include "algo/blazek/blazek_culling.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "algo/blazek/blazek_wire.hpp"
#include "scene/tessellate.hpp"

namespace zc::blazek {

bool object_may_touch(const NodeRenderer& nr, const Bytes& msg, const RowSet& rows,
                      std::uint32_t& triangles) {
  const auto got = decode_object(msg);
  if (!got) return true;
  triangles = got->header.triangle_count;
  if (got->header.is_mesh) return true;
  const ObjectSpec spec =
      parse_object_text(std::string(reinterpret_cast<const char*>(got->rest), got->rest_size));
  if (spec.kind == "bezier" || spec.kind == "mesh") return true;
  const glm::dmat4 m = nr.view().view_proj * spec.xf.to_matrix();
  double ylo = 1e300, yhi = -1e300;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec4 c =
        m * glm::dvec4(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1, 1);
    if (!(c.w > 1e-9) || !(c.z >= -c.w)) return true; // behind or across the near plane
    const double sy = (0.5 - 0.5 * c.y / c.w) * nr.height();
    ylo = std::min(ylo, sy);
    yhi = std::max(yhi, sy);
  }
  // Rows whose centres fall in [ylo, yhi], widened by a row for rounding.
  const int y0 = int(std::floor(ylo)) - 1, y1 = int(std::ceil(yhi)) + 1;
  const int first = rows.first_from(std::max(y0, 0));
  return first <= y1 && first < rows.end;
}

std::vector<std::uint32_t> triangles_touching(NodeContext& ctx, const NodeRenderer& nr,
                                              const ProjectedMesh& pm, const RowSet& rows) {
  std::vector<std::uint32_t> out;
  const auto n = std::uint32_t(pm.mesh.tris.size());
  for (std::uint32_t t = 0; t < n; ++t) {
    int y0, y1;
    if (!pm.rows(nr, t, y0, y1)) continue;
    const int first = rows.first_from(y0);
    if (first <= y1 && first < rows.end) out.push_back(t);
  }
  Counters k;
  k.triangles_estimated = n;
  ctx.charge(k);
  return out;
}

} // namespace zc::blazek
