// Blazek 1991, ch. II "Z-buffer Rendering", Algorithm 3: the node's z-buffer rendering of its
// polygons (blazek_render.hpp).
#include "algo/blazek/blazek_render.hpp"

#include "raster/zbuffer.hpp"

namespace zc::blazek {

void render_mesh(NodeContext& ctx, const NodeRenderer& nr, const ProjectedMesh& pm, Framebuffer& fb,
                 const std::vector<std::uint32_t>* subset) {
  Counters c;
  TriangleBatch batch;
  auto draw = [&](std::uint32_t t) {
    const TriangleRecord& tr = pm.mesh.tris[t];
    batch.clear();
    nr.setup(tr.id, tr.tri, pm.pv.data(), nullptr, batch, c); // untextured (check_scene)
    draw_batch(batch, nr.shade(), fb, c);
  };
  if (subset)
    for (std::uint32_t t : *subset)
      draw(t);
  else
    for (std::uint32_t t = 0; t < pm.mesh.tris.size(); ++t)
      draw(t);
  ctx.charge(c);
}

} // namespace zc::blazek
