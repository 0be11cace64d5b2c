// Charles, Lefevre, Miguet 1995, "An optimized and load-balanced portable parallel Zbuffer".
// §4 gives the program, which elastic_node below follows step by step:
//   Scatter(Vertices); Scatter(Triangles);                    elastic_scatter.cpp
//   for each picture:
//     project local vertices;
//     MultiBroadcast(projected vertices) (or §7's request)  elastic_vertices.cpp
//     LocalLoad = Estimation(local triangles);
//     GlobalLoad = MultiReduce(LocalLoad);                   elastic_load.cpp
//     MultiScatter(Triangles) to the slices they touch;
//     sequential z-buffer of the slice;
//     output the picture.                                    elastic_output.cpp
// §5 gives the load estimate (triangles per row, by a difference array and one scan) and the
// elastic cut of the rows into slices of equal estimated work (elastic_partition.cpp). Every step
// is a report phase.
#include "algo/charles/elastic.hpp"

#include <nlohmann/json.hpp>

#include "algo/charles/elastic_multiscatter.hpp"
#include "algo/charles/elastic_steps.hpp"
#include "algo/charles/elastic_vertices.hpp"
#include "algo/charles/elastic_wire.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "geometry/camera_path.hpp"
#include "raster/zbuffer.hpp"
#include "util/error.hpp"

namespace zc {

namespace elastic {
namespace {

std::vector<ProjectedVertex> project_vertices(NodeContext& ctx, const NodeRenderer& nr,
                                              const std::vector<Vertex>& vertices) {
  auto ph = ctx.phase("project");
  std::vector<ProjectedVertex> projected(vertices.size());
  Counters w;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    projected[i] = nr.project(vertices[i], w);
  ctx.charge(w);
  return projected;
}

// LocalLoad = Estimation(local triangles), §5: the rows each triangle covers, then the triangles
// per row by a difference array and one scan.
template <class Vertices>
LocalLoad estimate_load(NodeContext& ctx, const NodeRenderer& nr,
                        const std::vector<TriangleRecord>& tris, const Vertices& pv) {
  auto ph = ctx.phase("load_estimation");
  const int H = nr.height();
  LocalLoad load;
  load.extents.resize(tris.size());
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const Triangle& t = tris[i].tri;
    const ProjectedVertex* p[3] = {&pv.at(t.v[0]), &pv.at(t.v[1]), &pv.at(t.v[2])};
    RowExtent& e = load.extents[i];
    if (!nr.rows(tris[i].id, p, e.y0, e.y1)) e = {1, 0}; // covers no row
  }
  load.rows = scan_load(load_differences(load.extents, H), H);
  Counters w;
  w.triangles_estimated = tris.size();
  w.rows_scanned = std::uint64_t(H);
  ctx.charge(w);
  return load;
}

// MultiScatter(Triangles): each triangle to every slice it touches (duplicates, Table 1), by the
// loops of elastic_multiscatter.hpp. The paper's message is its triangles (records.hpp): the bytes
// charged are their records gathered from the block; the bitmask recovers the global ids of
// zcube's depth tie-break and is not charged.
template <class Vertices>
std::vector<typename Vertices::Record>
multiscatter_triangles(NodeContext& ctx, const LocalScene& local,
                       const std::vector<RowExtent>& extents, const std::vector<int>& bounds,
                       const Vertices& pv) {
  auto ph = ctx.phase("multiscatter_triangles");
  const int P = ctx.nodes();
  const bool with_material = materials_travel(ctx);
  const std::uint32_t material =
      ctx.scene().triangles.empty() ? 0 : ctx.scene().triangles.front().material;
  const std::size_t charged_record =
      kTriangleWireBytes + (with_material ? 4 : 0) + Vertices::kExtraRecordBytes;
  Counters gathered; // selected and written field by field
  SlicePayloads out = pack_slices(local.triangles, extents, bounds, with_material, pv, gathered);
  std::vector<Message> send(P);
  std::size_t gathered_bytes = 0;
  for (int k = 0; k < P; ++k) {
    send[k].payload = std::move(out.payloads[k]);
    send[k].charged = out.triangles[k] * charged_record;
    gathered_bytes += send[k].charged;
  }
  ctx.charge_packing(gathered_bytes);
  ctx.charge(gathered);
  std::vector<Payload> got; // read in place: shared payloads are not copied
  for (auto& m : coll::alltoallv(ctx.comm(), std::move(send)))
    got.push_back(std::move(m.payload));
  Counters read; // each received record read back field by field
  auto slice = read_slices<Vertices>(got, local.scene_triangles, with_material, material, read);
  ctx.charge(read);
  ctx.alloc(double(slice.size() * charged_record), "slice triangles");
  return slice;
}

// Sequential z-buffer of the slice (rows `rows`), in a frame buffer of its own.
template <class Vertices>
Framebuffer zbuffer_slice(NodeContext& ctx, const NodeRenderer& nr, const LocalScene& local,
                          const std::vector<typename Vertices::Record>& slice, const Vertices& pv,
                          const RowSet& rows) {
  auto ph = ctx.phase("zbuffer"); // the clear of the new buffer is the phase's (pixels_cleared)
  Framebuffer fb = nr.make_framebuffer(rows);
  ctx.alloc(double(fb.pixel_count() * records::charles::kZbufferLocation), "slice z-buffer");
  const glm::vec2* uvs = ctx.scene().textured() ? local.uvs.data() : nullptr;
  Counters w;
  w.pixels_cleared = fb.pixel_count();
  TriangleBatch batch;
  for (const auto& rec : slice) {
    const TriangleRecord& t = Vertices::triangle(rec);
    const ProjectedVertex* p[3];
    pv.vertices(rec, p);
    batch.clear();
    nr.setup_projected(t.id, t.tri, p, uvs, batch, w);
    draw_batch(batch, nr.shade(), fb, w);
  }
  ctx.charge(w);
  return fb;
}

// One picture of the animation: the loop body of §4, with the vertices exchanged as `Vertices`
// says.
template <class Vertices>
void render_picture(NodeContext& ctx, const LocalScene& local, int frame, bool gather) {
  const Scene& scene = ctx.scene();
  const int frames = ctx.options().frames, r = ctx.rank();
  const NodeRenderer nr(scene, camera_at_frame(scene.camera, frame, frames),
                        ctx.scene_facts().bounds);
  const auto my_pv = project_vertices(ctx, nr, local.vertices);
  Vertices pv;
  pv.exchange(ctx, local, my_pv); // MultiBroadcast(Projected Vertices), or §7's request
  ctx.alloc(pv.bytes, "projected vertices");
  const LocalLoad local_load = estimate_load(ctx, nr, local.triangles, pv);
  const auto global_load = multireduce_load(ctx, local_load.rows);
  const auto bounds = partition_rows(ctx, global_load);
  const auto slice = multiscatter_triangles(ctx, local, local_load.extents, bounds, pv);
  Framebuffer fb = zbuffer_slice(ctx, nr, local, slice, pv, RowSet::band(bounds[r], bounds[r + 1]));
  const std::size_t tri_record =
      triangle_wire_bytes(ctx) - kTriangleWireBytes + records::charles::kTriangle;
  const double held = double(fb.pixel_count() * records::charles::kZbufferLocation) + pv.bytes +
                      double(slice.size() * (tri_record + Vertices::kExtraRecordBytes));
  output_picture(ctx, std::move(fb), global_load,
                 {frame, frame == frames - 1, gather, slice.size(), scene.triangles.size()});
  ctx.release(held);
}

void elastic_node(NodeContext& ctx) {
  const std::string vertices = ctx.options().get("vertices");
  if (vertices != "broadcast" && vertices != "request")
    throw UsageError("--vertices must be broadcast or request");
  const std::string output = ctx.options().get("output");
  if (output != "device" && output != "gather")
    throw UsageError("--output must be device or gather");
  const bool gather = output == "gather";
  const std::string timed = ctx.options().get("timed");
  if (timed != "picture" && timed != "all" && !timed.empty())
    throw UsageError("--timed must be picture or all");

  const LocalScene local = scatter_scene(ctx);
  // §4: "The vertices come from a disk or from a previous computation on the parallel computer":
  // the scatters put the input in place; the speed-up times the per-picture loop against the
  // sequential z-buffer of a scene in memory (docs/papers.md). --timed all times them too.
  if (timed != "all") ctx.start_timed_region();
  if (ctx.rank() == 0) {
    // The records charged (records.hpp), and zcube's payloads where they differ.
    ctx.metrics()["wire_bytes"] = {
        {"vertex", records::charles::kVertex},
        {"projected_vertex", records::charles::kProjectedVertex},
        {"triangle", triangle_wire_bytes(ctx) - kTriangleWireBytes + records::charles::kTriangle},
        {"load_entry", records::charles::kLoadEntry}};
    ctx.metrics()["payload_bytes"] = {{"projected_vertex", sizeof(ProjectedVertex)}};
  }
  for (int f = 0; f < ctx.options().frames; ++f)
    if (vertices == "request")
      render_picture<RequestedVertices>(ctx, local, f, gather);
    else
      render_picture<BroadcastVertices>(ctx, local, f, gather);
}

} // namespace
} // namespace elastic

Algorithm elastic_algorithm() {
  Algorithm a;
  a.name = "elastic";
  a.summary = "Charles, Lefevre, Miguet 1995: elastic load-balanced image-space z-buffer";
  a.node = elastic::elastic_node;
  a.renders_frames = true;
  a.options = {{"vertices",
                OptionSpec::Kind::Choice,
                "broadcast",
                {"broadcast", "request"},
                0,
                0,
                "vertices every node receives: all (MultiBroadcast, §4) or those it asks for (§7)"},
               {"output",
                OptionSpec::Kind::Choice,
                "device",
                {"device", "gather"},
                0,
                0,
                "each node writes its slice to the output device, or node 0 gathers the picture"},
               {"timed",
                OptionSpec::Kind::Choice,
                "picture",
                {"picture", "all"},
                0,
                0,
                "the timed region: the per-picture loop (§4, the default) or the scatters too"}};
  return a;
}

} // namespace zc
