// Kurc, Aykanat, Ozguc: active pixel merging on hypercube multicomputers (iPSC/2). The node
// program below runs the paper's Table 2 columns as report phases:
//   distribute          triangles dealt round-robin to the nodes        kurc_span_lists.cpp
//   span_list_creation  projection, set-up, spans into x_min-sorted scanline lists (§2)
//   local_zbuffer       modified scanline z-buffer into the WPA, or a full z-buffer (ZBUF-EXC)
//   pixel_merging       global z-buffering so that each node ends with the final pixels of its
//                       share of the screen (§3, §4)                     kurc_merge_scheme.hpp
//   output              the picture gathered to node 0, and the paper's measures
#include "algo/kurc/kurc_pixel_merging.hpp"

#include <nlohmann/json.hpp>

#include "algo/composite.hpp"
#include "algo/kurc/kurc_merge_scheme.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "compositing/gather.hpp"
#include "compositing/winning_pixels.hpp"
#include "util/error.hpp"
#include "util/load_imbalance.hpp"

namespace zc {

namespace kurc {
namespace {

// Local z-buffer (§2, second step); returns the pixels generated (TPG).
std::uint64_t local_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const NodeSpans& spans,
                            MergeScheme& scheme) {
  auto ph = ctx.phase("local_zbuffer");
  Counters w;
  scheme.local_zbuffer(ctx, nr, spans, w);
  ctx.charge(w);
  return w.pixels_generated;
}

MergeMeasures pixel_merging(NodeContext& ctx, MergeScheme& scheme) {
  auto ph = ctx.phase("pixel_merging");
  Counters w;
  MergeMeasures m = scheme.merge(ctx, w);
  ctx.charge(w);
  return m;
}

// Node 0's report: the steps' largest messages (Fig. 1), merge loads (Fig. 2), TPG and TPF.
void record_measures(NodeContext& ctx, const MergeScheme& scheme, std::uint64_t tpf,
                     std::size_t steps, const std::vector<double>& step_max,
                     const std::vector<Bytes>& loads) {
  std::vector<std::uint64_t> merge_loads;
  std::uint64_t total_tpg = 0;
  for (const auto& b : loads) {
    auto v = unpack<std::uint64_t>(b);
    merge_loads.push_back(v[0]);
    total_tpg += v[1];
  }
  double volume = 0;
  for (double v : step_max)
    volume += v;
  auto& m = ctx.metrics();
  m["communication"] = {{"concurrent_volume_bytes", volume}, {"steps", steps}};
  m["load_imbalance"] = load_imbalance(merge_loads);
  // Bytes of the records the network and node memory are charged (records.hpp, docs/papers.md),
  // and of zcube's payloads (+ the triangle id of the depth tie-break; the dealt polygon's id,
  // material and vertex ids).
  m["wire_bytes"] = {{"pixel", records::kurc::kWinningPixel},
                     {"zbuffer_location", records::kurc::kZbufferLocation},
                     {"triangle", records::kurc::kPolygon},
                     {"count_entry", records::kurc::kCountEntry}};
  m["payload_bytes"] = {{"pixel", kWirePixelBytes},
                        {"zbuffer_location", Framebuffer::kLocationBytes},
                        {"triangle", sizeof(TriWorld)},
                        {"count_entry", sizeof(std::int32_t)}};
  m["kurc"] = {
      {"tpg", total_tpg}, {"tpf", tpf}, {"merge_loads", merge_loads}, {"scheme", scheme.name()}};
}

// Output: the final pixels of every node gathered to node 0, and the paper's measures.
void output(NodeContext& ctx, const NodeRenderer& nr, MergeScheme& scheme,
            const MergeMeasures& measures, std::uint64_t tpg) {
  auto ph = ctx.phase("output");
  Comm& c = ctx.comm();
  Counters packed;
  // Sent as the paper's records (9-byte pixels); zcube's copies are counted as it makes them.
  Message part = compositing::pack_pixels(scheme.final_pixels(packed), compositing::sparse_message,
                                          kurc_pixel_records(), packed);
  ctx.charge(packed);
  auto parts = compositing::gather(c, 0, std::move(part));
  auto step_max = coll::allreduce(c, measures.step_bytes, coll::Op::Max);
  auto loads = coll::gatherv(c, 0, pack(std::vector<std::uint64_t>{measures.merge_load, tpg}));
  if (c.rank() != 0) return;
  // Node 0 clears the picture and pastes every part into it.
  Framebuffer img = nr.make_framebuffer(RowSet::all(nr.height()));
  Counters w;
  w.pixels_cleared = img.pixel_count();
  // The nodes' final pixels are the picture's covered pixels (TPF), each written once: counted as
  // they are pasted, not by a scan of the picture (26 M locations at 5120x5120, zcube's
  // measurement, not the paper's program, inside the output phase).
  const std::uint64_t tpf = compositing::paste(parts, img, nr.height(), w);
  ctx.charge(w);
  record_measures(ctx, scheme, tpf, measures.step_bytes.size(), step_max, loads);
  ctx.deliver_image(0, std::move(img));
}

void kurc_node(NodeContext& ctx, MergeScheme& scheme) {
  if (ctx.comm().topology() != Topology::Cube)
    throw UsageError("Kurc et al.'s pixel merging runs on a hypercube (--topology cube)");
  const NodeRenderer nr(ctx.scene(), ctx.scene().camera, ctx.scene_facts().bounds);
  const NodeTriangles mine = distribute_triangles(ctx);
  // The timed region is Table 2's three columns: not the deal before them nor the output after
  // (docs/papers.md).
  ctx.start_timed_region();
  std::uint64_t tpg = 0;
  {
    const NodeSpans spans = create_span_lists(ctx, nr, mine);
    tpg = local_zbuffer(ctx, nr, spans, scheme);
    ctx.release(spans.bytes());
  }
  const MergeMeasures measures = pixel_merging(ctx, scheme);
  ctx.end_timed_region();
  output(ctx, nr, scheme, measures, tpg);
}

Algorithm make(const char* name, const char* summary,
               std::unique_ptr<MergeScheme> (*scheme)(const ScreenPartition&),
               const ScreenPartition& partition) {
  Algorithm a;
  a.name = name;
  a.summary = summary;
  a.node = [scheme, partition](NodeContext& ctx) { kurc_node(ctx, *scheme(partition)); };
  a.needs_cube = true;
  a.reference = "scanline"; // §1: each processor's sequential rendering, on one (docs/papers.md)
  return a;
}

std::unique_ptr<MergeScheme> zbuf_exc(const ScreenPartition&) {
  return make_zbuf_exc(); // its regions are the even halving of its exchange
}

} // namespace
} // namespace kurc

std::vector<Algorithm> kurc_algorithms() {
  using namespace kurc;
  return {
      make("zbuf-exc", "Kurc et al.: full z-buffer merging (every pixel location exchanged)",
           zbuf_exc, kEvenSplit),
      make("pair-rs", "Kurc et al.: pairwise exchange, recursive adaptive subdivision", make_pair,
           kRecursiveSubdivision),
      make("pair-hbp", "Kurc et al.: pairwise exchange, heuristic bin packing", make_pair,
           kHeuristicBinPacking),
      make("pair-even", "Kurc et al.: pairwise exchange, even split (unbalanced baseline)",
           make_pair, kEvenSplit),
      make("aapc-rs", "Kurc et al.: all-to-all personalized, recursive adaptive subdivision",
           make_aapc, kRecursiveSubdivision),
      make("aapc-hbp", "Kurc et al.: all-to-all personalized, heuristic bin packing", make_aapc,
           kHeuristicBinPacking),
      make("aapc-even", "Kurc et al.: all-to-all personalized, even split", make_aapc, kEvenSplit),
  };
}

} // namespace zc
