// Kurc, Aykanat, Ozguc §1-§2 on one node: the speed-ups' reference (docs/papers.md). The phases
// are the parallel schemes' first two Table 2 columns, with the same operations per polygon as a
// node of the schemes has for its share: each polygon with its three world vertices, a shared
// vertex transformed once, spans into x_min-sorted scanline lists, the modified scanline z-buffer.
#include "algo/scanline_baseline.hpp"

#include "algo/records.hpp"
#include "raster/active_pixels.hpp"
#include "raster/renderer.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

// A polygon as the node holds it: the schemes' dealt record (records.hpp).
constexpr double kPolygonBytes = records::kurc::kPolygon;

void scanline_node(NodeContext& ctx) {
  if (ctx.rank() != 0) return;
  const Scene& scene = ctx.scene();
  if (scene.textured()) throw UsageError("the scanline baseline renders untextured scenes");
  const int W = scene.width, H = scene.height;
  const NodeRenderer nr(scene);
  ctx.alloc(kPolygonBytes * double(scene.triangles.size()), "polygons");
  TriangleBatch batch;
  SpanLists lists;
  // The timed region: the schemes' first two Table 2 columns (docs/papers.md), the polygons
  // being already local.
  ctx.start_timed_region();
  {
    auto ph = ctx.phase("span_list_creation");
    Counters w;
    // The projected vertices (28 bytes each) are held until every triangle is set up.
    std::vector<ProjectedVertex> pv(scene.vertices.size());
    ctx.alloc(double(pv.size() * sizeof(ProjectedVertex)), "projected vertices");
    for (std::size_t i = 0; i < pv.size(); ++i)
      pv[i] = nr.project(scene.vertices[i], w);
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
      const Triangle& t = scene.triangles[i];
      const ProjectedVertex* p[3] = {&pv[t.v[0]], &pv[t.v[1]], &pv[t.v[2]]};
      nr.setup(std::uint32_t(i), t, p, nullptr, batch, w);
    }
    ctx.alloc(double(batch.tris.size() * sizeof(ScreenTriangle)), "set-up records");
    ctx.release(double(pv.size() * sizeof(ProjectedVertex)));
    lists = build_span_lists(batch, W, H, w);
    ctx.charge(w);
    ctx.alloc(double(lists.bytes()), "span lists");
  }
  ActivePixels wpa;
  {
    auto ph = ctx.phase("local_zbuffer");
    Counters w;
    ctx.alloc(double(W) * 4, "MSA");
    wpa = zbuffer_spans(lists, batch, nr.shade(), W, w);
    ctx.alloc(double(wpa.count() * records::kurc::kWinningPixel +
                     wpa.row_begin.size() * records::kurc::kCountEntry),
              "WPA");
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

Algorithm scanline_baseline_algorithm() {
  Algorithm a;
  a.name = "scanline";
  a.summary = "Kurc et al.'s one-node reference: modified scanline z-buffer, no frame buffer";
  a.node = scanline_node;
  a.reference = a.name;
  return a;
}

} // namespace zc
