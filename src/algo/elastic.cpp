// Charles, Lefevre, Miguet 1995, "An optimized and load-balanced portable parallel Zbuffer".
// §4 gives the program:
//   Scatter(Vertices); Scatter(Triangles);
//   for each picture: project local vertices; MultiBroadcast(projected vertices);
//     LocalLoad = Estimation(local triangles); GlobalLoad = MultiReduce(LocalLoad);
//     MultiScatter(Triangles) to the slices they touch; sequential z-buffer of the slice;
//     output the picture.
// §5 gives the load estimate (triangles per row, by a difference array and one scan) and the
// elastic cut of the rows into slices of equal estimated work. Every step is a report phase.
#include "algo/elastic.hpp"

#include <algorithm>
#include <unordered_map>

#include "algo/elastic_partition.hpp"
#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "geometry/camera_path.hpp"
#include "raster/renderer.hpp"
#include "raster/zbuffer.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

// A triangle as it travels: its global id (the depth tie-break), vertex indices and material.
struct TriRec {
  std::uint32_t id;
  std::uint32_t v[3];
  std::uint32_t material;
};
// In the request variant a migrating triangle carries its three projected vertices along.
struct TriWithVerts {
  TriRec t;
  ProjectedVertex pv[3];
};

// Block k of n items over P nodes: [k*n/P, (k+1)*n/P).
std::size_t block_lo(std::size_t n, int P, int k) {
  return n * std::size_t(k) / std::size_t(P);
}
int block_owner(std::size_t n, int P, std::size_t i) {
  // The k with block_lo(k) <= i < block_lo(k+1).
  int k = int((i * std::size_t(P)) / std::max<std::size_t>(n, 1));
  while (k + 1 < P && block_lo(n, P, k + 1) <= i)
    ++k;
  while (k > 0 && block_lo(n, P, k) > i)
    --k;
  return k;
}

Counters packed(std::size_t bytes) {
  Counters c;
  c.bytes_packed = bytes;
  return c;
}

void elastic_node(NodeContext& ctx) {
  Comm& c = ctx.comm();
  const int P = c.size(), r = c.rank();
  const Scene& scene = ctx.scene(); // node 0 reads it from disk; the others only get blocks
  const bool request = ctx.options().get("vertices", "broadcast") == "request";
  if (ctx.options().get("vertices", "broadcast") != "broadcast" && !request)
    throw UsageError("--vertices must be broadcast or request");
  const std::string output = ctx.options().get("output", "device");
  if (output != "device" && output != "gather")
    throw UsageError("--output must be device or gather");
  const bool gather = output == "gather";
  const std::size_t V = scene.vertices.size(), T = scene.triangles.size();
  const int H = scene.height;
  const bool textured = scene.textured();

  // Scatter(Vertices), Scatter(Triangles): equal contiguous blocks.
  std::vector<Vertex> my_vertices;
  std::vector<TriRec> my_tris;
  {
    auto ph = ctx.phase("scatter_vertices");
    std::vector<Bytes> parts;
    if (r == 0) {
      for (int k = 0; k < P; ++k)
        parts.push_back(pack(scene.vertices.data() + block_lo(V, P, k),
                             block_lo(V, P, k + 1) - block_lo(V, P, k)));
      ctx.charge(packed(V * sizeof(Vertex)));
    }
    my_vertices = unpack<Vertex>(coll::scatterv(c, 0, std::move(parts)));
    ctx.alloc(double(my_vertices.size() * sizeof(Vertex)), "vertex block");
  }
  {
    auto ph = ctx.phase("scatter_triangles");
    std::vector<Bytes> parts;
    if (r == 0) {
      for (int k = 0; k < P; ++k) {
        std::vector<TriRec> b;
        for (std::size_t i = block_lo(T, P, k); i < block_lo(T, P, k + 1); ++i) {
          const Triangle& t = scene.triangles[i];
          b.push_back({std::uint32_t(i), {t.v[0], t.v[1], t.v[2]}, t.material});
        }
        parts.push_back(pack(b));
      }
      ctx.charge(packed(T * sizeof(TriRec)));
    }
    my_tris = unpack<TriRec>(coll::scatterv(c, 0, std::move(parts)));
    ctx.alloc(double(my_tris.size() * sizeof(TriRec)), "triangle block");
  }
  // Texture coordinates do not change with the camera: multi-broadcast once, when textured.
  std::vector<glm::vec2> uvs;
  if (textured) {
    auto ph = ctx.phase("multibroadcast_uvs");
    const std::size_t lo = block_lo(V, P, r), hi = block_lo(V, P, r + 1);
    for (auto& b : coll::allgatherv(c, pack(scene.uvs.data() + lo, hi - lo))) {
      auto part = unpack<glm::vec2>(b);
      uvs.insert(uvs.end(), part.begin(), part.end());
    }
    ctx.alloc(double(uvs.size() * sizeof(glm::vec2)), "texture coordinates");
  }

  const std::size_t vlo = block_lo(V, P, r);
  const int frames = ctx.options().frames;
  for (int f = 0; f < frames; ++f) {
    const NodeRenderer nr(scene, camera_at_frame(scene.camera, f, frames));

    std::vector<ProjectedVertex> my_pv(my_vertices.size());
    {
      auto ph = ctx.phase("project");
      Counters w;
      for (std::size_t i = 0; i < my_vertices.size(); ++i)
        my_pv[i] = nr.project(my_vertices[i], w);
      ctx.charge(w);
    }

    // Projected vertices of the local triangles: all of them (MultiBroadcast) or just the ones
    // needed (request/answer, §7).
    std::vector<ProjectedVertex> all_pv;                         // broadcast: indexed by vertex
    std::unordered_map<std::uint32_t, ProjectedVertex> known_pv; // request: the needed ones
    double pv_bytes = 0;
    if (!request) {
      auto ph = ctx.phase("multibroadcast_vertices");
      all_pv.reserve(V);
      for (auto& b : coll::allgatherv(c, pack(my_pv))) {
        auto part = unpack<ProjectedVertex>(b);
        all_pv.insert(all_pv.end(), part.begin(), part.end());
      }
      pv_bytes = double(all_pv.size() * sizeof(ProjectedVertex));
      ctx.charge(packed(std::size_t(pv_bytes)));
    } else {
      auto ph = ctx.phase("request_vertices");
      std::vector<std::vector<std::uint32_t>> want(P);
      {
        std::vector<std::uint32_t> ids;
        for (const auto& t : my_tris)
          ids.insert(ids.end(), t.v, t.v + 3);
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        for (auto id : ids)
          want[block_owner(V, P, id)].push_back(id);
        Counters w;
        w.rows_scanned = ids.size(); // building the request lists
        ctx.charge(w);
      }
      std::vector<Bytes> req(P);
      for (int k = 0; k < P; ++k)
        req[k] = pack(want[k]);
      auto asked = coll::alltoallv(c, std::move(req));
      std::vector<Bytes> answers(P);
      for (int k = 0; k < P; ++k) {
        std::vector<ProjectedVertex> ans;
        for (auto id : unpack<std::uint32_t>(asked[k]))
          ans.push_back(my_pv[id - vlo]);
        answers[k] = pack(ans);
      }
      auto got = coll::alltoallv(c, std::move(answers));
      for (int k = 0; k < P; ++k) {
        auto pvs = unpack<ProjectedVertex>(got[k]);
        for (std::size_t i = 0; i < pvs.size(); ++i)
          known_pv[want[k][i]] = pvs[i];
      }
      pv_bytes = double(known_pv.size() * (sizeof(ProjectedVertex) + 4));
      ctx.charge(packed(std::size_t(pv_bytes)));
    }
    ctx.alloc(pv_bytes, "projected vertices");
    auto pv_of = [&](std::uint32_t id) -> const ProjectedVertex& {
      return request ? known_pv.at(id) : all_pv[id];
    };

    // LocalLoad = Estimation(local triangles) (§5 difference array + one scan).
    std::vector<RowExtent> ext(my_tris.size());
    std::vector<std::int64_t> local_load;
    {
      auto ph = ctx.phase("load_estimation");
      for (std::size_t i = 0; i < my_tris.size(); ++i) {
        const TriRec& t = my_tris[i];
        const ProjectedVertex* p[3] = {&pv_of(t.v[0]), &pv_of(t.v[1]), &pv_of(t.v[2])};
        if (!row_extent(p, scene.width, H, ext[i].y0, ext[i].y1)) ext[i] = {1, 0}; // no row
      }
      local_load = scan_load(load_differences(ext, H), H);
      Counters w;
      w.triangles_estimated = my_tris.size();
      w.rows_scanned = std::uint64_t(H);
      ctx.charge(w);
    }
    std::vector<std::int64_t> global_load;
    {
      auto ph = ctx.phase("multireduce_load");
      global_load = coll::allreduce(c, local_load, coll::Op::Sum);
      Counters w;
      w.rows_scanned = std::uint64_t(H) * std::uint64_t(std::max(1, c.dimension()));
      ctx.charge(w);
    }
    std::vector<int> bounds;
    {
      auto ph = ctx.phase("partition");
      bounds = elastic_partition(global_load, P);
      Counters w;
      w.rows_scanned = std::uint64_t(H);
      ctx.charge(w);
    }

    // MultiScatter(Triangles): each triangle to every slice it touches (duplicates, Table 1).
    std::vector<TriRec> slice_tris;
    std::vector<TriWithVerts> slice_tv;
    {
      auto ph = ctx.phase("multiscatter_triangles");
      std::vector<std::vector<TriRec>> out(P);
      std::vector<std::vector<TriWithVerts>> out_v(P);
      std::size_t bytes = 0;
      for (std::size_t i = 0; i < my_tris.size(); ++i) {
        if (ext[i].y0 > ext[i].y1) continue;
        // Slices overlapping rows [y0, y1].
        int k = int(std::upper_bound(bounds.begin(), bounds.end(), ext[i].y0) - bounds.begin()) - 1;
        for (; k < P && bounds[k] <= ext[i].y1; ++k) {
          if (bounds[k] == bounds[k + 1]) continue; // empty slice
          if (request) {
            const TriRec& t = my_tris[i];
            out_v[k].push_back({t, {pv_of(t.v[0]), pv_of(t.v[1]), pv_of(t.v[2])}});
            bytes += sizeof(TriWithVerts);
          } else {
            out[k].push_back(my_tris[i]);
            bytes += sizeof(TriRec);
          }
        }
      }
      ctx.charge(packed(bytes));
      std::vector<Bytes> send(P);
      for (int k = 0; k < P; ++k)
        send[k] = request ? pack(out_v[k]) : pack(out[k]);
      auto got = coll::alltoallv(c, std::move(send));
      for (int k = 0; k < P; ++k) {
        if (request) {
          auto v = unpack<TriWithVerts>(got[k]);
          slice_tv.insert(slice_tv.end(), v.begin(), v.end());
        } else {
          auto v = unpack<TriRec>(got[k]);
          slice_tris.insert(slice_tris.end(), v.begin(), v.end());
        }
      }
      ctx.alloc(double(slice_tris.size() * sizeof(TriRec) + slice_tv.size() * sizeof(TriWithVerts)),
                "slice triangles");
    }

    // Sequential z-buffer of the slice.
    const RowSet rows = RowSet::band(bounds[r], bounds[r + 1]);
    Framebuffer fb = nr.make_framebuffer(rows);
    const double fb_bytes = double(fb.bytes());
    ctx.alloc(fb_bytes, "slice z-buffer");
    const std::size_t n_slice = request ? slice_tv.size() : slice_tris.size();
    {
      auto ph = ctx.phase("zbuffer");
      Counters w;
      w.pixels_cleared = fb.pixel_count();
      TriangleBatch batch;
      for (std::size_t i = 0; i < n_slice; ++i) {
        const TriRec& t = request ? slice_tv[i].t : slice_tris[i];
        const ProjectedVertex* p[3];
        for (int k = 0; k < 3; ++k)
          p[k] = request ? &slice_tv[i].pv[k] : &all_pv[t.v[k]];
        const glm::vec2* uv[3] = {nullptr, nullptr, nullptr};
        if (textured)
          for (int k = 0; k < 3; ++k)
            uv[k] = &uvs[t.v[k]];
        batch.clear();
        const Triangle tri{{t.v[0], t.v[1], t.v[2]}, t.material};
        nr.setup(t.id, tri, p, textured ? uv : nullptr, batch, w);
        draw_batch(batch, nr.shade(), fb, w);
      }
      ctx.charge(w);
    }

    // Output of the picture (§4 "write the image to an output device"). --output device: each node
    // writes its slice to the device itself, so the communication volume does not depend on the
    // resolution (§6); --output gather: slices gathered to node 0 (colour only), which then holds
    // the picture.
    {
      auto ph = ctx.phase("output");
      std::vector<Bytes> parts;
      if (gather) {
        ctx.charge(packed(fb.rgb().size()));
        parts = coll::gatherv(c, 0, fb.rgb());
      }
      // Table 1 of the paper: per node triangles rendered, workload and rows.
      std::int64_t work = 0;
      for (int y = rows.begin; y < rows.end; ++y)
        work += global_load[y];
      const std::vector<std::int64_t> mine{std::int64_t(n_slice), work, rows.count()};
      auto stats = coll::gatherv(c, 0, pack(mine));
      if (!gather) ctx.deliver_rows(f, std::move(fb));
      if (r == 0) {
        Framebuffer full;
        if (gather) {
          full = nr.make_framebuffer(RowSet::all(H));
          for (int k = 0; k < P; ++k)
            std::copy(parts[k].begin(), parts[k].end(),
                      full.rgb().begin() + std::ptrdiff_t(3) * bounds[k] * scene.width);
          ctx.charge(packed(full.rgb().size()));
        }
        if (f == frames - 1) {
          std::int64_t total = 0;
          for (int y = 0; y < H; ++y)
            total += global_load[y];
          auto table = nlohmann::json::array();
          std::uint64_t sum_tris = 0;
          for (int k = 0; k < P; ++k) {
            auto s = unpack<std::int64_t>(stats[k]);
            sum_tris += std::uint64_t(s[0]);
            table.push_back({{"node", k},
                             {"triangles", s[0]},
                             {"workload", s[1]},
                             {"work_percent", total ? 100.0 * double(s[1]) / double(total) : 0.0},
                             {"rows", s[2]}});
          }
          ctx.metrics()["elastic"] = {
              {"slices", table},
              {"triangles_rendered", sum_tris},
              {"duplicated_triangles", std::int64_t(sum_tris) - std::int64_t(T)},
              {"vertices", ctx.options().get("vertices", "broadcast")},
              {"max_row_load", *std::max_element(global_load.begin(), global_load.end())}};
          std::vector<std::uint64_t> loads;
          for (const auto& s : table)
            loads.push_back(s["workload"].get<std::uint64_t>());
          const auto [mn, mx] = std::minmax_element(loads.begin(), loads.end());
          ctx.metrics()["load_imbalance"] = total ? double(*mx - *mn) / (double(total) / P) : 0.0;
        }
        if (gather) ctx.deliver_image(f, std::move(full));
      }
    }
    ctx.release(
        fb_bytes + pv_bytes +
        double(slice_tris.size() * sizeof(TriRec) + slice_tv.size() * sizeof(TriWithVerts)));
  }
}

} // namespace

Algorithm elastic_algorithm() {
  Algorithm a;
  a.name = "elastic";
  a.summary = "Charles, Lefevre, Miguet 1995: elastic load-balanced image-space z-buffer";
  a.node = elastic_node;
  a.option_keys = {"vertices", "output"};
  return a;
}

} // namespace zc
