// Kurc, Aykanat, Ozguc §1-§2 on one node: the speed-ups' reference (docs/papers.md). The phases
// are the parallel schemes' first two Table 2 columns, with the same operations per polygon as a
// node of the schemes has for its share: each polygon with its three world vertices, a shared
// vertex transformed once, spans into x_min-sorted scanline lists, the modified scanline z-buffer.
#include "algo/kurc/kurc_scanline.hpp"

#include "algo/kurc/kurc_span_lists.hpp"
#include "algo/records.hpp"
#include "raster/active_pixels.hpp"
#include "raster/renderer.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

void scanline_node(NodeContext& ctx) {
  if (ctx.rank() != 0) return;
  const Scene& scene = ctx.scene();
  if (scene.textured()) throw UsageError("the scanline baseline renders untextured scenes");
  const int H = scene.height;
  const NodeRenderer nr(scene, scene.camera, ctx.scene_facts().bounds);
  // The polygons as a node of the schemes holds its share: the dealt record (records.hpp).
  ctx.alloc(double(records::kurc::kPolygon) * double(scene.triangles.size()), "polygons");
  const kurc::NodeTriangles mine = kurc::all_triangles(scene);
  // The timed region: the schemes' first two Table 2 columns (docs/papers.md), the polygons
  // being already local.
  ctx.start_timed_region();
  const kurc::NodeSpans spans = kurc::create_span_lists(ctx, nr, mine);
  ActivePixels wpa;
  {
    auto ph = ctx.phase("local_zbuffer");
    Counters w;
    wpa = kurc::scanline_zbuffer(ctx, nr, spans, w);
    ctx.charge(w);
  }
  ctx.end_timed_region();
  // The WPA is the picture: the foremost pixels of every scanline. The device that shows it is
  // outside the modelled machine (no charge, no memory).
  Framebuffer img = nr.make_framebuffer(RowSet::all(H));
  scatter_active(wpa, img);
  ctx.deliver_image(0, std::move(img));
}

} // namespace

Algorithm kurc_scanline_algorithm() {
  Algorithm a;
  a.name = "scanline";
  a.summary = "Kurc et al.'s one-node reference: modified scanline z-buffer, no frame buffer";
  a.node = scanline_node;
  a.reference = a.name;
  return a;
}

} // namespace zc
