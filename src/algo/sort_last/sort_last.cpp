// Sort-last rendering on the compositing layer (sort_last.hpp): phases local_zbuffer,
// pixel_merging (the strategy) and output, as Kurc et al.'s program names them.
#include "algo/sort_last/sort_last.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "algo/composite.hpp"
#include "algo/kurc/kurc_merge_scheme.hpp"
#include "algo/kurc/kurc_partition.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "compositing/dense.hpp"
#include "compositing/gather.hpp"
#include "compositing/run_length.hpp"
#include "compositing/winning_pixels.hpp"
#include "util/block_split.hpp"
#include "util/error.hpp"
#include "util/load_imbalance.hpp"

namespace zc {

namespace {

using compositing::Picture;

// A node's local z-buffer in the representation chosen, and its scanlines' active pixel counts.
struct LocalPicture {
  std::unique_ptr<Picture> picture;
  std::vector<std::int32_t> row_pixels; // empty for a dense picture
  Message (*charge)(Bytes, const compositing::PixelRecords&) = compositing::sparse_message;
};

LocalPicture local_zbuffer(NodeContext& ctx, const NodeRenderer& nr, const kurc::NodeSpans& spans,
                           const std::string& kind) {
  auto ph = ctx.phase("local_zbuffer");
  Counters w;
  LocalPicture p;
  const auto rec = kurc_pixel_records();
  if (kind == "dense") {
    p.picture = compositing::dense(kurc::full_zbuffer(ctx, nr, spans, w), rec);
  } else {
    ctx.alloc(double(nr.width()) * 4, "MSA");
    ActivePixels a = zbuffer_spans(spans.lists, spans.batch, nr.shade(), nr.width(), w);
    const bool rle = kind == "run-length";
    ctx.alloc(rle ? compositing::run_length_bytes(a, rec) : compositing::held_bytes(a, rec),
              "active pixels");
    for (int y = 0; y < nr.height(); ++y)
      p.row_pixels.push_back(std::int32_t(a.row_count(y)));
    p.picture = rle ? compositing::run_length(std::move(a), rec)
                    : compositing::winning_pixels(std::move(a), rec);
    if (rle) p.charge = compositing::run_length_message;
  }
  ctx.charge(w);
  return p;
}

// The region: the active pixels shared by heuristic bin packing (§4.2) among the nodes that end
// owning rows, or equal strips of rows for a dense picture (every location travels).
std::vector<int> region(NodeContext& ctx, const LocalPicture& p, int owners, int height,
                        Counters& w) {
  if (p.row_pixels.empty()) {
    std::vector<int> owner(std::size_t(height), 0);
    for (int y = 0; y < height; ++y)
      owner[std::size_t(y)] = block_of(std::size_t(height), owners, std::size_t(y));
    return owner;
  }
  const auto global = coll::allreduce(ctx.comm(), p.row_pixels, coll::Op::Sum);
  w.rows_scanned += std::uint64_t(height) * 2;
  return heuristic_bin_packing(std::vector<std::uint64_t>(global.begin(), global.end()), owners);
}

// Node 0's report: the strategy, each step's largest message, the merge loads.
void record(NodeContext& ctx, const compositing::Strategy& s, const std::string& kind,
            const std::vector<Bytes>& measures) {
  std::vector<std::uint64_t> loads;
  std::vector<double> step_max;
  for (const auto& b : measures) {
    const auto v = unpack<double>(b);
    loads.push_back(std::uint64_t(v[0]));
    step_max.resize(std::max(step_max.size(), v.size() - 1), 0.0);
    for (std::size_t i = 1; i < v.size(); ++i)
      step_max[i - 1] = std::max(step_max[i - 1], v[i]);
  }
  double volume = 0;
  for (double v : step_max)
    volume += v;
  auto& m = ctx.metrics();
  m["communication"] = {{"concurrent_volume_bytes", volume}, {"steps", step_max.size()}};
  m["load_imbalance"] = load_imbalance(loads);
  m["compositing"] = {{"strategy", s.name},
                      {"picture", kind},
                      {"step_max_bytes", step_max},
                      {"merge_loads", loads}};
}

void output(NodeContext& ctx, const NodeRenderer& nr, Picture& picture, const LocalPicture& lp,
            const compositing::Strategy& s, const compositing::Measures& m) {
  auto ph = ctx.phase("output");
  Counters packed;
  Message part = compositing::pack_pixels(picture.final_pixels(packed), lp.charge,
                                          kurc_pixel_records(), packed);
  ctx.charge(packed);
  auto parts = compositing::gather(ctx.comm(), 0, std::move(part));
  std::vector<double> mine{double(m.merge_load)};
  mine.insert(mine.end(), m.step_bytes.begin(), m.step_bytes.end());
  auto measures = coll::gatherv(ctx.comm(), 0, pack(mine));
  if (ctx.rank() != 0) return;
  Framebuffer img = nr.make_framebuffer(RowSet::all(nr.height()));
  Counters w;
  w.pixels_cleared = img.pixel_count();
  compositing::paste(parts, img, nr.height(), w);
  ctx.charge(w);
  record(ctx, s, ctx.options().get("picture"), measures);
  ctx.deliver_image(0, std::move(img));
}

void sort_last_node(NodeContext& ctx, const compositing::Strategy& s) {
  const NodeRenderer nr(ctx.scene(), ctx.scene().camera, ctx.scene_facts().bounds);
  const kurc::NodeTriangles mine = kurc::distribute_triangles(ctx);
  ctx.start_timed_region();
  LocalPicture lp;
  {
    const kurc::NodeSpans spans = kurc::create_span_lists(ctx, nr, mine);
    lp = local_zbuffer(ctx, nr, spans, ctx.options().get("picture"));
    ctx.release(spans.bytes());
  }
  compositing::Measures m;
  {
    auto ph = ctx.phase("pixel_merging");
    Counters w;
    const auto owner = region(ctx, lp, s.owners(ctx.nodes()), nr.height(), w);
    m = composite(ctx, s, *lp.picture, owner, w, MergeCharge::ByRound);
    ctx.charge(w);
  }
  ctx.end_timed_region();
  output(ctx, nr, *lp.picture, lp, s, m);
}

std::vector<int> radix_option(const AlgorithmOptions& o) {
  std::vector<int> radix;
  const std::string v = o.get("radix");
  for (std::size_t at = 0; at < v.size();) {
    const std::size_t comma = std::min(v.find(',', at), v.size());
    radix.push_back(std::stoi(v.substr(at, comma - at)));
    at = comma + 1;
  }
  return radix;
}

compositing::Strategy configured(const compositing::Strategy& s, const AlgorithmOptions& o) {
  return s.name == "radix-k" ? compositing::radix_k(radix_option(o)) : s;
}

Algorithm make(const compositing::Strategy& s) {
  Algorithm a;
  a.name = "sort-last-" + s.name;
  a.summary = "sort-last rendering, then " + s.summary;
  a.node = [s](NodeContext& ctx) { sort_last_node(ctx, configured(s, ctx.options())); };
  a.reference = "scanline";
  a.options.push_back({"picture",
                       OptionSpec::Kind::Choice,
                       "winning-pixels",
                       {"dense", "winning-pixels", "run-length"},
                       0,
                       0,
                       "sort-last: the partial pictures composited: a full z-buffer, Kurc et al.'s "
                       "winning pixel array, or IceT's run-length encoded active pixels"});
  if (s.name == "radix-k")
    a.options.push_back({"radix",
                         OptionSpec::Kind::NodeList,
                         "4",
                         {},
                         2,
                         1024,
                         "radix-k: k for every round, or the factors of the node count, in order"});
  a.check_nodes = [s](const AlgorithmOptions& o, int nodes) {
    const std::string why = configured(s, o).refuses(nodes);
    if (!why.empty()) throw UsageError("--algorithm sort-last-" + s.name + ": " + why);
  };
  return a;
}

} // namespace

std::vector<Algorithm> sort_last_algorithms() {
  std::vector<Algorithm> v;
  for (const auto& s : compositing::strategies())
    v.push_back(make(s));
  return v;
}

} // namespace zc
