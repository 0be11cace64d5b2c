// The compositing study's node program (compositing_study.hpp). A contender is a strategy, a
// picture representation and a share of the screen. All-to-all rounds larger than largest_round
// are left out: a 1024-node direct send is 1,047,552 messages, seconds of host time on its own
// (docs/compositing.md, "The study"); `zcube run --algorithm aapc-hbp --nodes 1024` runs one.
#include "algo/sort_last/compositing_study.hpp"

#include <bit>

#include <nlohmann/json.hpp>

#include "algo/composite.hpp"
#include "algo/kurc/kurc_merge_scheme.hpp"
#include "algo/kurc/kurc_partition.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "compositing/run_length.hpp"
#include "compositing/winning_pixels.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

// Nodes in one all-to-all round: 64, 16 above 256 nodes (host time: a message costs the simulator
// tens of microseconds, and a 1024-node round of 64 is 64,512 of them).
int largest_round(int P) {
  return P > 256 ? 16 : 64;
}

struct Contender {
  std::string name;
  compositing::Strategy strategy;
  bool run_length = true;
  const ScreenPartition* share = &kHeuristicBinPacking;
};

std::vector<Contender> contenders(int P) {
  std::vector<Contender> v;
  if (std::has_single_bit(unsigned(P))) {
    v.push_back({"pair-rs", compositing::binary_swap(), false, &kRecursiveSubdivision});
    v.push_back({"binary-swap", compositing::binary_swap()});
  } else {
    v.push_back({"folding", compositing::folding()});
  }
  if (P <= largest_round(P)) {
    v.push_back({"aapc-hbp", compositing::direct_send(), false});
    v.push_back({"direct-send", compositing::direct_send()});
  }
  for (int k = 2; k < P; ++k) {
    if (P % k != 0 || (k == 2 && std::has_single_bit(unsigned(P))))
      continue; // radix-2 of 2^d: binary swap
    const auto rounds = compositing::radix_rounds(P, {k});
    if (*std::max_element(rounds.begin(), rounds.end()) > largest_round(P)) continue;
    v.push_back({"radix-" + std::to_string(k), compositing::radix_k({k})});
  }
  return v;
}

// The machine-wide active pixels of each scanline (§4.1), summed once for every contender.
std::vector<std::uint64_t> share_counts(NodeContext& ctx, const ActivePixels& local) {
  auto ph = ctx.phase("share");
  std::vector<std::int32_t> rows;
  for (int y = local.y0; y < local.y1; ++y)
    rows.push_back(std::int32_t(local.row_count(y)));
  const auto global = coll::allreduce(ctx.comm(), rows, coll::Op::Sum);
  return {global.begin(), global.end()};
}

// One contender from the node's local pixels, timed as its own phase after a barrier: the share
// of the screen, then the strategy.
compositing::Measures run(NodeContext& ctx, const Contender& c, const ActivePixels& local,
                          const std::vector<std::uint64_t>& counts) {
  coll::barrier(ctx.comm());
  auto ph = ctx.phase(c.name);
  Counters w;
  w.rows_scanned += std::uint64_t(counts.size());
  const std::vector<int> owner = c.share->owners(counts, c.strategy.owners(ctx.nodes()));
  const auto rec = kurc_pixel_records();
  auto picture =
      c.run_length ? compositing::run_length(local, rec) : compositing::winning_pixels(local, rec);
  auto m = composite(ctx, c.strategy, *picture, owner, w, MergeCharge::ByRound);
  ctx.charge(w);
  return m;
}

void study_node(NodeContext& ctx) {
  const NodeRenderer nr(ctx.scene(), ctx.scene().camera, ctx.scene_facts().bounds);
  const kurc::NodeTriangles mine = kurc::distribute_triangles(ctx);
  ActivePixels local;
  {
    const kurc::NodeSpans spans = kurc::create_span_lists(ctx, nr, mine);
    auto ph = ctx.phase("local_zbuffer");
    Counters w;
    local = zbuffer_spans(spans.lists, spans.batch, nr.shade(), nr.width(), w);
    ctx.charge(w);
  }
  const auto counts = share_counts(ctx, local);
  const auto all = contenders(ctx.nodes());
  std::vector<double> sent, messages;
  for (const auto& c : all) {
    const auto m = run(ctx, c, local, counts);
    sent.push_back(0);
    for (double b : m.step_bytes)
      sent.back() += b;
    messages.push_back(double(m.step_bytes.size()));
  }
  // The most bytes and messages any node sent, for each contender.
  sent.insert(sent.end(), messages.begin(), messages.end());
  const auto most = coll::allreduce(ctx.comm(), sent, coll::Op::Max);
  if (ctx.rank() != 0) return;
  nlohmann::json steps = nlohmann::json::object();
  for (std::size_t i = 0; i < all.size(); ++i)
    steps[all[i].name] = {{"max_bytes_sent", most[i]}, {"max_messages", most[all.size() + i]}};
  ctx.metrics()["compositing_study"] = steps;
}

} // namespace

std::vector<std::string> compositing_contenders(int nodes) {
  std::vector<std::string> v;
  for (const auto& c : contenders(nodes))
    v.push_back(c.name);
  return v;
}

std::vector<Algorithm> compositing_study_algorithms() {
  Algorithm a;
  a.name = "compositing-study";
  a.summary = "every compositing strategy in turn from the same local pictures (reproduce "
              "compositing)";
  a.node = study_node;
  a.draws_picture = false;
  a.reference = "scanline";
  a.check_nodes = [](const AlgorithmOptions&, int nodes) {
    if (nodes < 2) throw UsageError("--algorithm compositing-study: at least 2 nodes");
  };
  return {a};
}

} // namespace zc
