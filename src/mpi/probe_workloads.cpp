#include "mpi/probe_workloads.hpp"

#include <algorithm>
#include <memory>

#include "algo/charles/elastic_multiscatter.hpp"
#include "algo/charles/elastic_partition.hpp"
#include "algo/charles/elastic_vertices.hpp"
#include "algo/composite.hpp"
#include "compositing/dense.hpp"
#include "compositing/gather.hpp"
#include "compositing/winning_pixels.hpp"
#include "mpi/probe_groups.hpp"
#include "raster/active_pixels.hpp"
#include "raster/zbuffer.hpp"
#include "scene/prng.hpp"
#include "scene/tessellate.hpp"
#include "scene/vertex_order.hpp"

namespace zc::cpu_probe {

namespace {

// The frame-buffer z-buffer as elastic's slices and Blazek's nodes run it: each triangle set up,
// then drawn, into `fb` cleared before each call. Every argument must outlive p.run().
void time_zbuffer_loop(Probe& p, const std::string& what, const Scene& s, const NodeRenderer& nr,
                       const std::vector<ProjectedVertex>& pv, Framebuffer& fb) {
  p.time(
      kZbufferLoops, what, [&] { fb.clear(nr.background()); },
      [&s, &nr, &pv, &fb, one = TriangleBatch{}](Counters& c) mutable {
        for (std::size_t i = 0; i < s.triangles.size(); ++i) {
          one.clear();
          nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, one, c);
          draw_batch(one, nr.shade(), fb, c);
        }
      });
}

// Two nodes of a pair (Kurc et al.'s PAIR at P = 2): the picture's triangles dealt round-robin, as
// Kurc's distribute deals them, each node's winning pixels over every row. Their lists interleave
// in the same rows, as a pair's merge finds them (the odd rows of one picture merged into its even
// rows, as the probe did before, meet empty rows: each row a copy of one list, not a merge).
struct PairInputs {
  ActivePixels a, b;
  ActivePixels a_even, b_even;     // the rows node a keeps, of each node
  std::vector<int> to_odd;         // node a's routing: its odd rows to node b
  std::vector<std::uint8_t> b_msg; // node b's even rows on the wire, as node a receives them
};
PairInputs pair_inputs(const Scene& s, const NodeRenderer& nr,
                       const std::vector<ProjectedVertex>& pv, int size) {
  Counters ignored;
  TriangleBatch half[2];
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, half[i % 2], ignored);
  PairInputs in;
  for (int k = 0; k < 2; ++k) {
    const SpanLists lists = build_span_lists(half[k], size, size, ignored);
    (k == 0 ? in.a : in.b) = zbuffer_spans(lists, half[k], nr.shade(), size, ignored);
  }
  in.to_odd.assign(static_cast<std::size_t>(size), -1);
  std::vector<int> to_even(static_cast<std::size_t>(size), -1);
  for (int y = 0; y < size; ++y)
    (y % 2 ? in.to_odd : to_even)[std::size_t(y)] = y % 2;
  in.b_msg = std::move(serialize_sparse_by_owner(in.b, to_even, 2)[0]);
  in.a_even = select_rows(in.a, [](int y) { return y % 2 == 0; });
  in.b_even = select_rows(in.b, [](int y) { return y % 2 == 0; });
  return in;
}

// A pair's merge of its kept rows with its partner's (the list merge, `merge_active`), and its
// exchange as zcube makes it (compositing/winning_pixels.cpp): the rows sent converted to wire
// records, the rows kept copied out, the partner's rows merged into them from the wire. `in` must
// outlive p.run().
void time_pair_loops(Probe& p, const std::string& name, const PairInputs& in) {
  p.time(kListMergeLoops, name,
         [&in](Counters& c) { (void)merge_active(in.a_even, in.b_even, c); });
  p.time(kWireLoops, name, [&in](Counters& c) {
    const auto parts = serialize_sparse_by_owner(in.a, in.to_odd, 2);
    const ActivePixels keep = select_rows(in.a, [](int y) { return y % 2 == 0; });
    std::uint64_t got = 0;
    (void)merge_active_sparse(keep, in.b_msg.data(), in.b_msg.size(), c, got);
    c.wire_records += in.a.count() + got;
  });
}

// The frame-buffer z-buffer's inputs with the picture's triangles in a scattered order (a fixed
// shuffle): the same triangles, spans and fragments as in file order, their far lines many more,
// as a scanned mesh listed without locality has them (the bunny's file: docs/machines.md). The
// vertices follow the shuffled triangles (renumbered by first use): read in a shuffled order
// (the bone's 1.1 MB of projected vertices: more than a second-level cache of 1 MB), each
// triangle's three would miss that cache too, a cost no counter has, which the fit put on the far
// lines; the workloads read theirs in the order of a mesh listed with locality.
struct ScatteredScene {
  Scene s;
  NodeRenderer nr;
  std::vector<ProjectedVertex> pv;
  Framebuffer fb;
  explicit ScatteredScene(const ProbeScene& ps)
      : s(shuffled(ps.scene)), nr(s), pv(probe_projected_vertices(nr, s)),
        fb(nr.make_framebuffer(RowSet::all(ps.size))) {}
  static Scene shuffled(Scene s) {
    SplitMix64 rng(20261202);
    for (std::size_t i = s.triangles.size(); i > 1; --i)
      std::swap(s.triangles[i - 1], s.triangles[rng.next() % i]);
    renumber_vertices_by_first_use(s);
    return s;
  }
};

} // namespace

// The loops of one scene at one size: projection, set-up, the frame-buffer z-buffer (set-up and
// scan conversion, as elastic's slices and Blazek's nodes run it), Kurc et al.'s span lists and
// active pixel z-buffer, the load estimate. `kurc`: also the active merge and the output (final
// pixels packed, unpacked and pasted into the picture), on this picture's active pixels.
// Also the z-buffer on the triangles scattered (ScatteredScene), timed in the same rounds as in
// file order: the fit prices far lines on the difference, and timed apart, minutes later, the
// host's drift between the two went into it.
void render_loops(Probe& p, const ProbeScene& ps, bool kurc) {
  const Scene& s = ps.scene;
  const int size = ps.size;
  const NodeRenderer nr(s);
  const std::vector<ProjectedVertex> pv = probe_projected_vertices(nr, s);
  Counters ignored;
  // The inputs of the later loops, made once: every triangle set up, the span lists, the active
  // pixels, the frame buffers.
  TriangleBatch all;
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, all, ignored);
  SpanLists lists = build_span_lists(all, size, size, ignored);
  ActivePixels wpa = zbuffer_spans(lists, all, nr.shade(), size, ignored);
  Framebuffer fb = nr.make_framebuffer(RowSet::all(size));
  Framebuffer picture = kurc ? nr.make_framebuffer(RowSet::all(size)) : Framebuffer{};
  std::vector<ProjectedVertex> pv2(pv.size());
  p.time(kProjectLoops, ps.name, [&](Counters& c) {
    for (std::size_t i = 0; i < pv2.size(); ++i)
      pv2[i] = nr.project(s.vertices[i], c);
  });
  TriangleBatch one;
  auto setup = [&](std::size_t i, Counters& c) {
    one.clear();
    nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, one, c);
  };
  p.time(kSetupLoops, ps.name, [&](Counters& c) {
    for (std::size_t i = 0; i < s.triangles.size(); ++i)
      setup(i, c);
  });
  p.time(
      kZbufferLoops, ps.name, [&] { fb.clear(nr.background()); },
      [&](Counters& c) {
        for (std::size_t i = 0; i < s.triangles.size(); ++i) {
          setup(i, c);
          draw_batch(one, nr.shade(), fb, c);
        }
      });
  const auto scattered = std::make_unique<ScatteredScene>(ps);
  time_zbuffer_loop(p, ps.name + " scattered", scattered->s, scattered->nr, scattered->pv,
                    scattered->fb);
  std::vector<RowExtent> ext(s.triangles.size());
  p.time(kEstimateLoops, ps.name, [&](Counters& c) {
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
      const Triangle& t = s.triangles[i];
      const ProjectedVertex* p3[3] = {&pv[t.v[0]], &pv[t.v[1]], &pv[t.v[2]]};
      if (!row_extent(p3, size, size, ext[i].y0, ext[i].y1)) ext[i] = {1, 0};
    }
    const auto rows = scan_load(load_differences(ext, size), size);
    c.triangles_estimated = s.triangles.size();
    c.rows_scanned = rows.size();
  });
  p.time(kSpanListLoops, ps.name, [&](Counters& c) { (void)build_span_lists(all, size, size, c); });
  p.time(kActiveLoops, ps.name,
         [&](Counters& c) { (void)zbuffer_spans(lists, all, nr.shade(), size, c); });
  if (kurc) {
    const PairInputs pair = pair_inputs(s, nr, pv, size);
    time_pair_loops(p, ps.name, pair);
    // Kurc et al.'s output (compositing/gather.hpp): the final pixels packed into a message, which
    // node 0 unpacks and pastes into the picture.
    p.time(kOutputLoops, ps.name, [&](Counters& c) {
      std::vector<Message> parts;
      parts.push_back(
          compositing::pack_pixels(wpa, compositing::sparse_message, kurc_pixel_records(), c));
      compositing::paste(parts, picture, size, c);
    });
    // ZBUF-EXC's final pixels (compositing/dense.cpp): every location of a full z-buffer of this
    // picture scanned, each covered one made a record.
    Framebuffer full = nr.make_framebuffer(RowSet::all(size));
    scatter_active(wpa, full);
    const auto dense = compositing::dense(std::move(full), kurc_pixel_records());
    p.time(kDenseOutputLoops, ps.name, [&](Counters& c) { (void)dense->final_pixels(c); });
    p.run();
    return;
  }
  p.run();
}

// Kurc et al.'s active z-buffer (`zbuffer_spans`) on every second triangle of the picture (dealt
// round-robin, as a pair's node gets them: about twice the share of pixels appended), and with
// `whole` on all of them too. Its span lists are made once, untimed.
void active_loops(Probe& p, const ProbeScene& ps, bool whole) {
  const Scene& s = ps.scene;
  const NodeRenderer nr(s);
  const std::vector<ProjectedVertex> pv = probe_projected_vertices(nr, s);
  Counters ignored;
  TriangleBatch all, half;
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, all, ignored);
    if (i % 2 == 0) nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, half, ignored);
  }
  const SpanLists all_lists = build_span_lists(all, ps.size, ps.size, ignored);
  const SpanLists half_lists = build_span_lists(half, ps.size, ps.size, ignored);
  if (whole)
    p.time(kActiveLoops, ps.name,
           [&](Counters& c) { (void)zbuffer_spans(all_lists, all, nr.shade(), ps.size, c); });
  p.time(kActiveLoops, ps.name + " one node of two",
         [&](Counters& c) { (void)zbuffer_spans(half_lists, half, nr.shade(), ps.size, c); });
  p.run();
}

// The frame-buffer z-buffer in the picture's middle band of rows whose depth the recent-lines
// window holds (RecentLines::kWindow lines: 32 rows at 4096, 256 at 512), on the triangles that
// enter it, as one of elastic's slices draws them: no far line, so the block's loops determine
// edges, spans and fragments without them (on whole pictures, fragments and far lines grow
// together and traded cost from one probe to the next: docs/machines.md). The band's depth, ids
// and colours (about 1.4 MB) stay in this machine's 2 MB L2, as the window assumes.
void near_loops(Probe& p, const ProbeScene& ps) {
  const Scene& s = ps.scene;
  const int size = ps.size;
  const int rows = std::min(size, int(RecentLines::kWindow * RecentLines::kLocations) / size);
  const int y0 = (size - rows) / 2;
  const NodeRenderer nr(s);
  const std::vector<ProjectedVertex> pv = probe_projected_vertices(nr, s);
  std::vector<std::size_t> in_band; // the slice's triangles (elastic's MultiScatter sends these)
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const Triangle& t = s.triangles[i];
    const ProjectedVertex* p3[3] = {&pv[t.v[0]], &pv[t.v[1]], &pv[t.v[2]]};
    int a = 0, b = 0;
    if (row_extent(p3, size, size, a, b) && a < y0 + rows && b >= y0) in_band.push_back(i);
  }
  Framebuffer fb = nr.make_framebuffer(RowSet::band(y0, y0 + rows));
  p.time(
      kNearZbufferLoops,
      ps.name + " rows " + std::to_string(y0) + "-" + std::to_string(y0 + rows - 1),
      [&] { fb.clear(nr.background()); },
      [&, one = TriangleBatch{}](Counters& c) mutable {
        for (std::size_t i : in_band) {
          one.clear();
          nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, one, c);
          draw_batch(one, nr.shade(), fb, c);
        }
      });
  p.run();
}

// Charles et al.'s MultiScatter of triangles (elastic_multiscatter.hpp) among `nodes` nodes, all
// in this process: each node's block of the picture's triangles packed for the slices of equal
// rows, then each slice read out of its messages; the records' bytes as elastic charges them.
void multiscatter_loops(Probe& p, const ProbeScene& ps, int nodes) {
  const Scene& s = ps.scene;
  const NodeRenderer nr(s);
  const std::vector<ProjectedVertex> pv = probe_projected_vertices(nr, s);
  const std::size_t T = s.triangles.size();
  std::vector<std::vector<TriangleRecord>> blocks(nodes);
  std::vector<std::vector<RowExtent>> ext(nodes);
  for (int k = 0; k < nodes; ++k)
    for (std::size_t i = block_range(T, nodes, k).begin; i < block_range(T, nodes, k).end; ++i) {
      const Triangle& t = s.triangles[i];
      const ProjectedVertex* p3[3] = {&pv[t.v[0]], &pv[t.v[1]], &pv[t.v[2]]};
      RowExtent e;
      if (!row_extent(p3, ps.size, ps.size, e.y0, e.y1)) e = {1, 0};
      blocks[k].push_back({std::uint32_t(i), t});
      ext[k].push_back(e);
    }
  std::vector<int> bounds;
  for (int k = 0; k <= nodes; ++k)
    bounds.push_back(int(block_begin(std::size_t(ps.size), nodes, k)));
  const elastic::BroadcastVertices none;
  p.time(kMultiScatterLoops, ps.name + " " + std::to_string(nodes) + " nodes", [&](Counters& c) {
    std::vector<elastic::SlicePayloads> sent;
    for (int k = 0; k < nodes; ++k) {
      sent.push_back(elastic::pack_slices(blocks[k], ext[k], bounds, false, none, c));
      for (std::size_t n : sent.back().triangles)
        c.bytes_packed += n * elastic::kTriangleWireBytes;
    }
    for (int r = 0; r < nodes; ++r) {
      std::vector<Payload> got; // read in place, as elastic.cpp reads them
      for (int k = 0; k < nodes; ++k)
        got.push_back(std::move(sent[k].payloads[r]));
      (void)elastic::read_slices<elastic::BroadcastVertices>(got, T, false, 0, c);
    }
  });
  p.run();
}

// Blazek's nodes: the thesis's spheres (the workloads' triangles, as few or as many a sphere)
// tessellated, then set up and drawn into the node's frame buffer.
void sphere_loops(Probe& p, const ProbeScene& ps) {
  const Scene& s = ps.scene;
  const NodeRenderer nr(s);
  const std::vector<ProjectedVertex> pv = probe_projected_vertices(nr, s);
  Framebuffer fb = nr.make_framebuffer(RowSet::all(ps.size));
  TriangleBatch one;
  p.time(kTessellateLoops, ps.name, [&](Counters& c) {
    for (const ObjectDesc& d : s.objects)
      if (d.kind != "mesh") c.triangles_tessellated += tessellate(d).triangles.size();
  });
  p.time(kSetupLoops, ps.name, [&](Counters& c) {
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
      one.clear();
      nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, one, c);
    }
  });
  time_zbuffer_loop(p, ps.name, s, nr, pv, fb);
  p.run();
}

// Frame buffers: a new one (allocation and clear: what make_framebuffer costs), locations packed
// into a message and merged back (the full z-buffer merges).
void buffer_loops(Probe& p, int size, bool merges) {
  const std::string name = std::to_string(size) + "x" + std::to_string(size);
  p.time(kClearLoops, name, [&](Counters& c) {
    Framebuffer fb(size, RowSet::all(size), glm::vec3(0));
    c.pixels_cleared = fb.pixel_count();
  });
  Framebuffer a, b;
  std::vector<std::uint8_t> msg;
  if (merges) {
    a = Framebuffer(size, RowSet::all(size), glm::vec3(0));
    b = a;
    for (std::size_t i = 0; i < b.depth().size(); i += 3) {
      b.depth()[i] = float(i % 7) * 0.1f;
      b.ids()[i] = std::uint32_t(i);
    }
    msg = b.pack_locations(0, b.pixel_count());
    p.time(kPackingLoops, name,
           [&](Counters& c) { c.bytes_packed = b.pack_locations(0, b.pixel_count()).size(); });
    p.time(kMergeLoops, name, [&](Counters& c) { c.merge_ops = a.merge_locations(msg, 0); });
  }
  p.run();
}

} // namespace zc::cpu_probe
