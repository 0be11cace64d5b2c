// Kurc, Aykanat, Ozguc: active pixel merging on hypercube multicomputers (iPSC/2).
// Phases as the paper's Table 2 columns: span_list_creation (projection, set-up, spans into
// x_min-sorted scanline lists), local_zbuffer (modified scanline z-buffer into the WPA, or a full
// z-buffer for ZBUF-EXC), pixel_merging (global z-buffering so that each node ends with the
// final pixels of its share of the screen). Before them the triangles are dealt round-robin to
// the nodes (distribute), after them the picture is gathered to node 0 (output).
#include "algo/kurc_pixel_merging.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <unordered_map>

#include "algo/merge_partition.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "raster/active_pixels.hpp"
#include "raster/renderer.hpp"
#include "raster/zbuffer.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

enum class Merge { Pair, Aapc, ZbufExc };
enum class Split { RS, HBP, Even };

// A triangle dealt to a node: its global id, material and world-space vertices (with their ids,
// so shared vertices are transformed once per node).
struct TriWorld {
  std::uint32_t id, material;
  std::uint32_t vid[3];
  Vertex v[3];
};
struct TriUV {
  glm::vec2 uv[3];
};

constexpr int kTagPair = 100, kTagZbuf = 200;

Counters packed(std::size_t bytes) {
  Counters c;
  c.bytes_packed = bytes;
  return c;
}

// True when the rows y in [0, h) with in(y) form more than one run: such a message has to be
// gathered from several places of the WPA (a copy); one run is sent in place.
template <class Pred> bool fragmented(int h, Pred in) {
  int runs = 0;
  for (int y = 0; y < h; ++y)
    runs += in(y) && (y == 0 || !in(y - 1));
  return runs > 1;
}

// Full-z-buffer message: every location of rows [y0, y1): rgb, depth, id (11 bytes each).
Bytes pack_locations(const Framebuffer& fb, int y0, int y1) {
  const std::size_t w = std::size_t(fb.width()), a = std::size_t(y0) * w;
  const std::size_t n = y1 > y0 ? std::size_t(y1 - y0) * w : 0;
  Bytes out(11 * n);
  if (n == 0) return out;
  std::memcpy(out.data(), fb.rgb().data() + 3 * a, 3 * n);
  std::memcpy(out.data() + 3 * n, fb.depth().data() + a, 4 * n);
  std::memcpy(out.data() + 7 * n, fb.ids().data() + a, 4 * n);
  return out;
}

void node_main(NodeContext& ctx, Merge merge, Split split) {
  Comm& c = ctx.comm();
  const int P = c.size(), r = c.rank(), d = c.dimension();
  if (c.topology() != Topology::Cube)
    throw UsageError("Kurc et al.'s pixel merging runs on a hypercube (--topology cube)");
  const Scene& scene = ctx.scene();
  const int W = scene.width, H = scene.height;
  const bool textured = scene.textured();
  const NodeRenderer nr(scene);

  // Distribute: triangle i to node i mod P, with its world vertices (node 0 reads the scene).
  std::vector<TriWorld> tris;
  std::vector<TriUV> tri_uv;
  {
    auto ph = ctx.phase("distribute");
    std::vector<Bytes> parts(P), uv_parts(P);
    if (r == 0) {
      std::vector<std::vector<TriWorld>> per(P);
      std::vector<std::vector<TriUV>> per_uv(P);
      for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& t = scene.triangles[i];
        TriWorld w{std::uint32_t(i),
                   t.material,
                   {t.v[0], t.v[1], t.v[2]},
                   {scene.vertices[t.v[0]], scene.vertices[t.v[1]], scene.vertices[t.v[2]]}};
        per[i % P].push_back(w);
        if (textured)
          per_uv[i % P].push_back({{scene.uvs[t.v[0]], scene.uvs[t.v[1]], scene.uvs[t.v[2]]}});
      }
      for (int k = 0; k < P; ++k) {
        parts[k] = pack(per[k]);
        if (textured) uv_parts[k] = pack(per_uv[k]);
      }
      ctx.charge(packed(scene.triangles.size() * sizeof(TriWorld)));
    }
    tris = unpack<TriWorld>(coll::scatterv(c, 0, std::move(parts)));
    if (textured) tri_uv = unpack<TriUV>(coll::scatterv(c, 0, std::move(uv_parts)));
    ctx.alloc(double(tris.size() * sizeof(TriWorld) + tri_uv.size() * sizeof(TriUV)), "triangles");
  }

  // Span list creation (§2, first step).
  TriangleBatch batch;
  SpanLists lists;
  {
    auto ph = ctx.phase("span_list_creation");
    Counters w;
    std::unordered_map<std::uint32_t, ProjectedVertex> pv;
    for (const auto& t : tris)
      for (int k = 0; k < 3; ++k)
        if (!pv.count(t.vid[k])) pv.emplace(t.vid[k], nr.project(t.v[k], w));
    for (std::size_t i = 0; i < tris.size(); ++i) {
      const TriWorld& t = tris[i];
      const ProjectedVertex* p[3] = {&pv[t.vid[0]], &pv[t.vid[1]], &pv[t.vid[2]]};
      const glm::vec2* uv[3] = {nullptr, nullptr, nullptr};
      if (textured)
        for (int k = 0; k < 3; ++k)
          uv[k] = &tri_uv[i].uv[k];
      nr.setup(t.id, Triangle{{t.vid[0], t.vid[1], t.vid[2]}, t.material}, p,
               textured ? uv : nullptr, batch, w);
    }
    lists = build_span_lists(batch, W, H, w);
    ctx.charge(w);
    ctx.alloc(double(lists.bytes() + batch.tris.size() * sizeof(ScreenTriangle)), "span lists");
  }

  // Local z-buffer (§2, second step): WPA through the MSA, or a full z-buffer for ZBUF-EXC.
  ActivePixels wpa;
  Framebuffer full;
  std::uint64_t tpg = 0;
  {
    auto ph = ctx.phase("local_zbuffer");
    Counters w;
    if (merge == Merge::ZbufExc) {
      full = nr.make_framebuffer(RowSet::all(H));
      ctx.alloc(double(full.bytes()), "full z-buffer");
      w.pixels_cleared = std::uint64_t(W) * H;
      for (int y = 0; y < H; ++y)
        for (std::uint32_t s = lists.row_begin[y]; s < lists.row_begin[y + 1]; ++s) {
          const SpanRecord& sp = lists.spans[s];
          const ScreenTriangle& t = batch.tris[sp.tri];
          const RowShader rs(t, batch, nr.shade(), y);
          for (int x = sp.x0; x <= sp.x1; ++x) {
            const std::size_t i = full.index(x, y);
            const float z = rs.depth(x);
            if (!in_front(z, t.id, full.depth()[i], full.ids()[i])) continue;
            std::uint8_t rgb[3];
            rs.color(x, rgb, w);
            full.test_and_write(i, z, t.id, rgb);
            ++w.pixels_written;
          }
          w.pixels_generated += std::uint64_t(sp.x1 - sp.x0 + 1);
          w.pixels_tested += std::uint64_t(sp.x1 - sp.x0 + 1);
        }
    } else {
      ctx.alloc(double(W) * 4, "MSA");
      wpa = zbuffer_spans(lists, batch, nr.shade(), W, w);
      ctx.alloc(double(wpa.bytes()), "WPA");
    }
    tpg = w.pixels_generated;
    ctx.charge(w);
  }
  ctx.release(double(lists.bytes() + batch.tris.size() * sizeof(ScreenTriangle)));
  lists = SpanLists{};
  batch.clear();

  // Pixel merging (§3, §4).
  std::vector<double> step_bytes; // bytes this node sent at each communication step
  std::uint64_t merge_load = 0;   // pixel merging operations of this node (Fig. 2)
  std::vector<int> owner;         // scanline -> node at the end of merging
  ActivePixels mine;              // final pixels of my scanlines (active merging)
  {
    auto ph = ctx.phase("pixel_merging");
    // Packing is charged only for messages gathered from several runs of scanlines: the local
    // foremost pixels are stored in consecutive memory locations precisely so that a message
    // over one run is a contiguous region, sent and merged in place (Kurc et al. §2), as a full
    // z-buffer's half is. zcube's own copies into Bytes are an artefact of its wire format.
    Counters w;
    if (merge == Merge::ZbufExc) {
      // Recursive halving over all pixel locations: stage i halves the current band and swaps
      // halves with the neighbour over channel i; every location of the half is compared.
      owner = even_split(H, P);
      int y0 = 0, y1 = H;
      for (int i = 0; i < d; ++i) {
        const int partner = r ^ (1 << i), mid = y0 + (y1 - y0) / 2;
        const bool top = !(r & (1 << i));
        const int sy0 = top ? mid : y0, sy1 = top ? y1 : mid; // half that leaves
        Bytes out = pack_locations(full, sy0, sy1);
        step_bytes.push_back(double(out.size()));
        auto h = c.isend(partner, kTagZbuf + i, std::move(out));
        Bytes in = c.recv(partner, kTagZbuf + i);
        h->wait();
        const int ky0 = top ? y0 : mid, ky1 = top ? mid : y1;
        const std::size_t n = std::size_t(ky1 - ky0) * W, base = std::size_t(ky0) * W;
        const std::uint8_t* rgb = in.data();
        const float* z = reinterpret_cast<const float*>(in.data() + 3 * n);
        std::vector<float> zs(z, z + n);
        std::vector<std::uint32_t> ids(n);
        std::memcpy(ids.data(), in.data() + 7 * n, 4 * n);
        for (std::size_t k = 0; k < n; ++k)
          if (in_front(zs[k], ids[k], full.depth()[base + k], full.ids()[base + k])) {
            full.depth()[base + k] = zs[k];
            full.ids()[base + k] = ids[k];
            std::memcpy(&full.rgb()[3 * (base + k)], rgb + 3 * k, 3);
          }
        w.merge_ops += n;
        merge_load += n;
        y0 = ky0;
        y1 = ky1;
      }
    } else {
      // Per-scanline counts of local foremost pixels, summed over the machine (§4.1).
      std::vector<std::int64_t> counts(H);
      for (int y = 0; y < H; ++y)
        counts[y] = wpa.row_count(y);
      const auto global = coll::allreduce(c, counts, coll::Op::Sum);
      std::vector<std::uint64_t> rows(global.begin(), global.end());
      owner = split == Split::RS    ? recursive_subdivision(rows, P)
              : split == Split::HBP ? heuristic_bin_packing(rows, P)
                                    : even_split(H, P);
      w.rows_scanned = std::uint64_t(H) * std::uint64_t(std::max(1, d) + 1);
      if (merge == Merge::Pair) {
        // §3.1: d divide-and-exchange stages; at stage i keep the scanlines whose owner agrees
        // with me on bit i, send the others over channel i, merge what arrives.
        mine = std::move(wpa);
        for (int i = 0; i < d; ++i) {
          const int bit = 1 << i, partner = r ^ bit;
          auto give = select_rows(mine, [&](int y) { return (owner[y] & bit) != (r & bit); });
          auto keep = select_rows(mine, [&](int y) { return (owner[y] & bit) == (r & bit); });
          Bytes out = serialize_sparse(give);
          if (fragmented(H, [&](int y) { return (owner[y] & bit) != (r & bit); }))
            w.bytes_packed += out.size();
          step_bytes.push_back(double(out.size()));
          auto h = c.isend(partner, kTagPair + i, std::move(out));
          Bytes in = c.recv(partner, kTagPair + i);
          h->wait();
          ActivePixels got = deserialize_sparse(in.data(), in.size(), W, 0, H);
          ctx.alloc(double(in.size()), "receive buffer");
          merge_load += got.count();
          mine = merge_active(keep, got, w);
          ctx.release(double(in.size()));
        }
      } else {
        // §3.2: every subregion's pixels straight to its owner (pairwise e-cube schedule over
        // disjoint paths), then z-buffer local and received pixels into the owned scanlines.
        std::vector<Bytes> out(P);
        for (int k = 0; k < P; ++k) {
          out[k] = serialize_sparse(select_rows(wpa, [&](int y) { return owner[y] == k; }));
          if (k != r && fragmented(H, [&](int y) { return owner[y] == k; }))
            w.bytes_packed += out[k].size();
          if (k != r) {
            step_bytes.push_back(double(out[k].size())); // step (r XOR k) carries this one
          }
        }
        // Re-order the per-destination sizes by step: step k exchanges with r ^ k.
        std::vector<double> by_step(std::size_t(std::max(0, P - 1)), 0.0);
        for (int k = 1; k < P; ++k)
          by_step[k - 1] = double(out[r ^ k].size());
        step_bytes = by_step;
        auto in = coll::alltoallv(c, std::move(out), coll::AllToAll::Pairwise);
        mine = deserialize_sparse(in[r].data(), in[r].size(), W, 0, H);
        for (int k = 0; k < P; ++k) {
          if (k == r) continue;
          ActivePixels got = deserialize_sparse(in[k].data(), in[k].size(), W, 0, H);
          merge_load += got.count();
          mine = merge_active(mine, got, w);
        }
      }
      std::uint64_t owned_rows = 0;
      for (int y = 0; y < H; ++y)
        owned_rows += owner[y] == r;
      ctx.alloc(double(owned_rows) * W * 11.0, "z-buffer of the owned scanlines");
    }
    ctx.charge(w);
  }

  // Output: the final pixels of every node gathered to node 0, and the paper's measures.
  {
    auto ph = ctx.phase("output");
    Bytes part;
    if (merge == Merge::ZbufExc) {
      int y0 = 0, y1 = H;
      for (int i = 0; i < d; ++i) {
        const int mid = y0 + (y1 - y0) / 2;
        if (!(r & (1 << i)))
          y1 = mid;
        else
          y0 = mid;
      }
      ActivePixels a;
      a.width = W;
      a.y0 = y0;
      a.y1 = y1;
      a.row_begin.assign(std::size_t(y1 - y0) + 1, 0);
      for (int y = y0; y < y1; ++y) {
        for (int x = 0; x < W; ++x) {
          const std::size_t i = full.index(x, y);
          if (full.ids()[i] == kNoTriangle) continue;
          WinningPixel p{full.depth()[i], full.ids()[i], std::uint16_t(x), {}};
          std::memcpy(p.rgb, &full.rgb()[3 * i], 3);
          a.pixels.push_back(p);
        }
        a.row_begin[y - y0 + 1] = std::uint32_t(a.pixels.size());
      }
      part = serialize_sparse(a);
    } else {
      part = serialize_sparse(mine);
    }
    ctx.charge(packed(part.size()));
    auto parts = coll::gatherv(c, 0, std::move(part));
    // Measures: steps' largest messages (Fig. 1) and merge loads (Fig. 2).
    const std::size_t steps = step_bytes.size();
    auto step_max = coll::allreduce(c, step_bytes, coll::Op::Max);
    auto loads = coll::gatherv(c, 0, pack(std::vector<std::uint64_t>{merge_load, tpg}));
    if (r == 0) {
      Framebuffer img = nr.make_framebuffer(RowSet::all(H));
      for (const auto& b : parts)
        scatter_active(deserialize_sparse(b.data(), b.size(), W, 0, H), img);
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
      m["kurc"] = {{"tpg", total_tpg},
                   {"tpf", img.covered()},
                   {"merge_loads", merge_loads},
                   {"scheme", merge == Merge::ZbufExc ? "zbuf-exc"
                              : merge == Merge::Pair  ? "pair"
                                                      : "aapc"}};
      ctx.deliver_image(0, std::move(img));
    }
  }
}

Algorithm make(const char* name, const char* summary, Merge m, Split s) {
  Algorithm a;
  a.name = name;
  a.summary = summary;
  a.node = [m, s](NodeContext& ctx) { node_main(ctx, m, s); };
  return a;
}

} // namespace

std::vector<Algorithm> kurc_algorithms() {
  return {
      make("zbuf-exc", "Kurc et al.: full z-buffer merging (every pixel location exchanged)",
           Merge::ZbufExc, Split::Even),
      make("pair-rs", "Kurc et al.: pairwise exchange, recursive adaptive subdivision", Merge::Pair,
           Split::RS),
      make("pair-hbp", "Kurc et al.: pairwise exchange, heuristic bin packing", Merge::Pair,
           Split::HBP),
      make("pair-even", "Kurc et al.: pairwise exchange, even split (unbalanced baseline)",
           Merge::Pair, Split::Even),
      make("aapc-rs", "Kurc et al.: all-to-all personalized, recursive adaptive subdivision",
           Merge::Aapc, Split::RS),
      make("aapc-hbp", "Kurc et al.: all-to-all personalized, heuristic bin packing", Merge::Aapc,
           Split::HBP),
      make("aapc-even", "Kurc et al.: all-to-all personalized, even split", Merge::Aapc,
           Split::Even),
  };
}

} // namespace zc
