#include "mpi/probe_cpu.hpp"

#include <malloc.h>
#include <time.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>

#include "algo/charles/elastic_multiscatter.hpp"
#include "algo/charles/elastic_partition.hpp"
#include "algo/charles/elastic_vertices.hpp"
#include "algo/composite.hpp"
#include "compositing/dense.hpp"
#include "compositing/gather.hpp"
#include "compositing/winning_pixels.hpp"
#include "machine/cpu_model.hpp"
#include "raster/active_pixels.hpp"
#include "raster/renderer.hpp"
#include "raster/zbuffer.hpp"
#include "scene/load.hpp"
#include "scene/prng.hpp"
#include "scene/tessellate.hpp"
#include "scene/vertex_order.hpp"
#include "util/nnls.hpp"

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define ZC_CALLGRIND 1
#endif

namespace zc {

void premap_heap(std::size_t bytes) {
  mallopt(M_MMAP_MAX, 0);                // every block from the heap, none mapped apart
  mallopt(M_TRIM_THRESHOLD, 0x7fffffff); // freed memory stays mapped
  mallopt(M_TOP_PAD, 64 << 20);          // the heap grows by 64 MiB at a time beyond it
  void* p = std::malloc(bytes);
  if (!p) return;
  // One write a page, through a volatile pointer: a memset of memory freed next is a dead store
  // the compiler removes (and the pages would stay unmapped).
  volatile char* page = static_cast<volatile char*>(p);
  for (std::size_t i = 0; i < bytes; i += 4096)
    page[i] = 1;
  std::free(p);
}

namespace {

// This thread's CPU time: what a loop costs the CPU, whatever else the machine runs meanwhile (on
// an idle machine, its wall-clock time).
double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// The probe's cost groups, in the order they are measured: one multiplier each on the prior table
// (the 80386's physical estimate keeps the proportions inside a group). Each block of loops below
// measures its own groups with every group measured before it subtracted at the cost found.
enum Group : std::size_t {
  kVertex,
  kTriangle,
  kEstimate,
  kTessellate,
  kClear,
  kPacking,
  kMerge,
  kListMerge,
  kRecords,
  kTriangleRecords,
  kEdges,
  kSpans,
  kPixels,
  kFarLines,
  kDistantLines,
  kSort,
  kWpaTested,
  kWpaAppended,
  kRecordFetches,
  kScan,
  kWire,
  kGroups
};

const std::vector<CostGroup>& probe_groups() {
  static const std::vector<CostGroup> g = {
      {"vertex", {"vertices_transformed"}},
      {"triangle", {"triangles_in", "triangles_culled", "triangles_clipped", "triangles_setup"}},
      {"estimate", {"triangles_estimated", "rows_scanned"}},
      {"tessellate", {"triangles_tessellated"}},
      {"clear", {"pixels_cleared"}},
      {"packing", {"bytes_packed", "wire_bytes"}},
      {"merge", {"merge_ops"}},
      {"list_merge", {"list_merges"}},
      {"records", {"records_packed"}},
      {"triangle records", {"triangles_packed"}},
      {"edges", {"edge_walks"}},
      {"spans", {"spans", "span_starts"}},
      {"pixels",
       {"pixels_generated", "pixels_tested", "pixels_written", "pixels_final", "texels_fetched"}},
      {"far lines", {"far_lines"}},
      {"distant lines", {"distant_lines"}},
      {"sort", {"sort_steps"}},
      {"wpa tested", {"wpa_tested"}},
      {"wpa appended", {"wpa_appended"}},
      {"record fetches", {"records_fetched"}},
      {"scan", {"locations_scanned"}},
      {"wire", {"wire_records"}}};
  return g;
}

// The blocks of loops, in the order they are solved (blocks()).
enum BlockId : std::size_t {
  kProjectLoops,
  kSetupLoops,
  kEstimateLoops,
  kTessellateLoops,
  kClearLoops,
  kPackingLoops,
  kMergeLoops,
  kListMergeLoops,
  kWireLoops,
  kOutputLoops,
  kDenseOutputLoops,
  kMultiScatterLoops,
  kNearZbufferLoops,
  kZbufferLoops,
  kSpanListLoops,
  kActiveLoops,
};

// A block: the groups its loops measure, solved together (most blocks have one).
struct Block {
  const char* name;
  std::vector<std::size_t> groups;
};
const std::vector<Block>& blocks() {
  static const std::vector<Block> b = {
      {"project", {kVertex}},
      {"set-up", {kTriangle}},
      {"load estimate", {kEstimate}},
      {"tessellate", {kTessellate}},
      {"clear", {kClear}},
      {"location packing", {kPacking}},
      {"location merge", {kMerge}},
      {"active merge", {kListMerge}},
      {"wire records", {kWire}},
      {"sparse output", {kRecords}},
      {"dense output", {kScan}},
      {"multiscatter", {kTriangleRecords}},
      // The frame-buffer z-buffer in a band of rows whose depth the recent-lines window holds (no
      // far line): a triangle's edges, its spans (found and started), its fragments; the scenes'
      // and sizes' different mixes separate them.
      {"near z-buffer", {kEdges, kSpans, kPixels}},
      // The frame-buffer z-buffer on whole pictures, less the above: its far lines (the scattered
      // orders: the same triangles, other far lines), and of them the distant ones, from main
      // memory rather than the last-level cache's share (the bone at 1024, 2048 and 4096: frame
      // buffers of 12, 50 and 200 MB; at 512, 3 MB, it has none).
      {"z-buffer", {kFarLines, kDistantLines}},
      {"span lists", {kSort}},
      // Kurc et al.'s active z-buffer, less its span starts and fragments: a pixel tested through
      // the MSA and one appended to the WPA, apart (zcube's loop: about 5 and 41 instructions;
      // the 80386's ratio, 3.4 : 1 for tested, does not hold here). The bone at every size
      // appends one pixel for three tested; its triangles dealt to two nodes two for three, the
      // three bones one for ten (the twelve bunnies' mix) and dealt to two nodes one for five.
      // A span's set-up record fetched from memory (records_fetched), with them: every active loop
      // fetches some, at rates its mix does not follow (a span: the bone at 4096 0.08, at 2048
      // 0.11, at 512 0.31; the three bones at 2048 0.23; the bone's half at 4096 0.03).
      {"active z-buffer", {kWpaTested, kWpaAppended, kRecordFetches}}};
  return b;
}

struct Loop {
  std::size_t block;
  std::string name;
  Counters c;
  double seconds;
  std::size_t calls;
};

struct Probe {
  double min_s;
  const ProbeRanks& ranks;
  std::vector<Loop> loops;       // every rank at once
  std::vector<Loop> loops_alone; // rank 0 alone (times_alone), the other ranks waiting

  struct Job {
    std::size_t block;
    std::string name;
    std::function<void()> prep;
    std::function<void(Counters&)> fn;
    Counters c;
    std::vector<double> t, t_alone;
  };
  std::vector<Job> jobs;

  // Registers a loop: fn timed, `prep` run before each call untimed, the counters fn counts
  // recorded. run() times the registered loops.
  void time(std::size_t block, const std::string& what, std::function<void()> prep,
            std::function<void(Counters&)> fn) {
    jobs.push_back({block,
                    std::string(blocks()[block].name) + " " + what,
                    std::move(prep),
                    std::move(fn),
                    {},
                    {},
                    {}});
  }
  void time(std::size_t block, const std::string& what, std::function<void(Counters&)> fn) {
    time(
        block, what, [] {}, std::move(fn));
  }

  // Every registered loop in turn, each called until it has run a third of min_s; its times go
  // to `alone` or to the at-once series. Under callgrind every call's instructions are dumped
  // apart, named after the loop (scripts/probe_instructions.py).
  void round(bool alone) {
    for (Job& j : jobs) {
#ifdef ZC_CALLGRIND
      const std::string dump_name = "probe loop: " + j.name;
#endif
      double spent = 0;
      do {
        j.prep();
        j.c = Counters{};
#ifdef ZC_CALLGRIND
        CALLGRIND_ZERO_STATS;
#endif
        const double t0 = cpu_now();
        j.fn(j.c);
        const double s = cpu_now() - t0;
#ifdef ZC_CALLGRIND
        CALLGRIND_DUMP_STATS_AT(dump_name.c_str());
#endif
        (alone ? j.t_alone : j.t).push_back(s);
        spent += s;
      } while (spent < min_s / kRounds);
    }
  }

  // The registered loops, three rounds; each round times them first on rank 0 alone, then on
  // every rank at once. A change of the machine's load meanwhile falls on all the loops, not on
  // those timed last (the blocks subtract one loop's costs from another's), and on the alone and
  // at-once times alike: their ratio, what a node loses to the others sharing the memory system,
  // is taken in the same minutes (timed one after the other, two probes found a rank 17 % faster
  // with the other cores busy than alone). A loop's time is the median of its calls.
  static constexpr int kRounds = 3;
  void run() {
    for (int r = 0; r < kRounds; ++r) {
      if (ranks.times_alone) round(true);
      ranks.wait();
      round(false);
      ranks.wait();
    }
    const auto median = [](std::vector<double>& t) {
      std::sort(t.begin(), t.end());
      return t[t.size() / 2];
    };
    for (Job& j : jobs) {
      loops.push_back({j.block, j.name, j.c, median(j.t), j.t.size()});
      if (!j.t_alone.empty())
        loops_alone.push_back({j.block, j.name, j.c, median(j.t_alone), j.t_alone.size()});
    }
    jobs.clear();
  }
};

struct Picture {
  Scene s;
  std::string name;
  int size;
};

Picture load(const std::string& path, int size) {
  LoadOptions lo;
  lo.width = lo.height = size;
  Picture p{load_scene(path, lo), "", size};
  p.name = p.s.path.substr(p.s.path.find_last_of('/') + 1) + " " + std::to_string(size) + "x" +
           std::to_string(size);
  return p;
}

// Every vertex of `s` projected by `nr` (the loops' inputs; their counts are not timed).
std::vector<ProjectedVertex> probe_projected_vertices(const NodeRenderer& nr, const Scene& s) {
  std::vector<ProjectedVertex> pv(s.vertices.size());
  Counters ignored;
  for (std::size_t i = 0; i < pv.size(); ++i)
    pv[i] = nr.project(s.vertices[i], ignored);
  return pv;
}

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
struct ScatteredPicture {
  Scene s;
  NodeRenderer nr;
  std::vector<ProjectedVertex> pv;
  Framebuffer fb;
  explicit ScatteredPicture(const Picture& pic)
      : s(shuffled(pic.s)), nr(s), pv(probe_projected_vertices(nr, s)),
        fb(nr.make_framebuffer(RowSet::all(pic.size))) {}
  static Scene shuffled(Scene s) {
    SplitMix64 rng(20261202);
    for (std::size_t i = s.triangles.size(); i > 1; --i)
      std::swap(s.triangles[i - 1], s.triangles[rng.next() % i]);
    renumber_vertices_by_first_use(s);
    return s;
  }
};

// The loops of one scene at one size: projection, set-up, the frame-buffer z-buffer (set-up and
// scan conversion, as elastic's slices and Blazek's nodes run it), Kurc et al.'s span lists and
// active pixel z-buffer, the load estimate. `kurc`: also the active merge and the output (final
// pixels packed, unpacked and pasted into the picture), on this picture's active pixels.
// Also the z-buffer on the triangles scattered (ScatteredPicture), timed in the same rounds as in
// file order: the fit prices far lines on the difference, and timed apart, minutes later, the
// host's drift between the two went into it.
void render_loops(Probe& p, const Picture& pic, bool kurc) {
  const Scene& s = pic.s;
  const int size = pic.size;
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
  p.time(kProjectLoops, pic.name, [&](Counters& c) {
    for (std::size_t i = 0; i < pv2.size(); ++i)
      pv2[i] = nr.project(s.vertices[i], c);
  });
  TriangleBatch one;
  auto setup = [&](std::size_t i, Counters& c) {
    one.clear();
    nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, one, c);
  };
  p.time(kSetupLoops, pic.name, [&](Counters& c) {
    for (std::size_t i = 0; i < s.triangles.size(); ++i)
      setup(i, c);
  });
  p.time(
      kZbufferLoops, pic.name, [&] { fb.clear(nr.background()); },
      [&](Counters& c) {
        for (std::size_t i = 0; i < s.triangles.size(); ++i) {
          setup(i, c);
          draw_batch(one, nr.shade(), fb, c);
        }
      });
  const auto scattered = std::make_unique<ScatteredPicture>(pic);
  time_zbuffer_loop(p, pic.name + " scattered", scattered->s, scattered->nr, scattered->pv,
                    scattered->fb);
  std::vector<RowExtent> ext(s.triangles.size());
  p.time(kEstimateLoops, pic.name, [&](Counters& c) {
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
      const Triangle& t = s.triangles[i];
      const ProjectedVertex* p3[3] = {&pv[t.v[0]], &pv[t.v[1]], &pv[t.v[2]]};
      if (!row_extent(p3, size, size, ext[i].y0, ext[i].y1)) ext[i] = {1, 0};
    }
    const auto rows = scan_load(load_differences(ext, size), size);
    c.triangles_estimated = s.triangles.size();
    c.rows_scanned = rows.size();
  });
  p.time(kSpanListLoops, pic.name,
         [&](Counters& c) { (void)build_span_lists(all, size, size, c); });
  p.time(kActiveLoops, pic.name,
         [&](Counters& c) { (void)zbuffer_spans(lists, all, nr.shade(), size, c); });
  if (kurc) {
    const PairInputs pair = pair_inputs(s, nr, pv, size);
    time_pair_loops(p, pic.name, pair);
    // Kurc et al.'s output (compositing/gather.hpp): the final pixels packed into a message, which
    // node 0 unpacks and pastes into the picture.
    p.time(kOutputLoops, pic.name, [&](Counters& c) {
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
    p.time(kDenseOutputLoops, pic.name, [&](Counters& c) { (void)dense->final_pixels(c); });
    p.run();
    return;
  }
  p.run();
}

// Kurc et al.'s active z-buffer (`zbuffer_spans`) on every second triangle of the picture (dealt
// round-robin, as a pair's node gets them: about twice the share of pixels appended), and with
// `whole` on all of them too. Its span lists are made once, untimed.
void active_loops(Probe& p, const Picture& pic, bool whole) {
  const Scene& s = pic.s;
  const NodeRenderer nr(s);
  const std::vector<ProjectedVertex> pv = probe_projected_vertices(nr, s);
  Counters ignored;
  TriangleBatch all, half;
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, all, ignored);
    if (i % 2 == 0) nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, half, ignored);
  }
  const SpanLists all_lists = build_span_lists(all, pic.size, pic.size, ignored);
  const SpanLists half_lists = build_span_lists(half, pic.size, pic.size, ignored);
  if (whole)
    p.time(kActiveLoops, pic.name,
           [&](Counters& c) { (void)zbuffer_spans(all_lists, all, nr.shade(), pic.size, c); });
  p.time(kActiveLoops, pic.name + " one node of two",
         [&](Counters& c) { (void)zbuffer_spans(half_lists, half, nr.shade(), pic.size, c); });
  p.run();
}

// The frame-buffer z-buffer in the picture's middle band of rows whose depth the recent-lines
// window holds (RecentLines::kWindow lines: 32 rows at 4096, 256 at 512), on the triangles that
// enter it, as one of elastic's slices draws them: no far line, so the block's loops determine
// edges, spans and fragments without them (on whole pictures, fragments and far lines grow
// together and traded cost from one probe to the next: docs/machines.md). The band's depth, ids
// and colours (about 1.4 MB) stay in this machine's 2 MB L2, as the window assumes.
void near_loops(Probe& p, const Picture& pic) {
  const Scene& s = pic.s;
  const int size = pic.size;
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
      pic.name + " rows " + std::to_string(y0) + "-" + std::to_string(y0 + rows - 1),
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
void multiscatter_loops(Probe& p, const Picture& pic, int nodes) {
  const Scene& s = pic.s;
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
      if (!row_extent(p3, pic.size, pic.size, e.y0, e.y1)) e = {1, 0};
      blocks[k].push_back({std::uint32_t(i), t});
      ext[k].push_back(e);
    }
  std::vector<int> bounds;
  for (int k = 0; k <= nodes; ++k)
    bounds.push_back(int(block_begin(std::size_t(pic.size), nodes, k)));
  const elastic::BroadcastVertices none;
  p.time(kMultiScatterLoops, pic.name + " " + std::to_string(nodes) + " nodes", [&](Counters& c) {
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
void sphere_loops(Probe& p, const Picture& pic) {
  const Scene& s = pic.s;
  const NodeRenderer nr(s);
  const std::vector<ProjectedVertex> pv = probe_projected_vertices(nr, s);
  Framebuffer fb = nr.make_framebuffer(RowSet::all(pic.size));
  TriangleBatch one;
  p.time(kTessellateLoops, pic.name, [&](Counters& c) {
    for (const ObjectDesc& d : s.objects)
      if (d.kind != "mesh") c.triangles_tessellated += tessellate(d).triangles.size();
  });
  p.time(kSetupLoops, pic.name, [&](Counters& c) {
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
      one.clear();
      nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, one, c);
    }
  });
  time_zbuffer_loop(p, pic.name, s, nr, pv, fb);
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

// The table the probe's multipliers scale: the 80386's physical estimates, and for a far line, a
// distant line (what it costs beyond a far line) and a set-up record fetched (nothing on the
// 80386, whose memory has one level: operations.json) a nominal 100 ns, a DRAM access of this
// era, their multipliers a fraction of it.
CostTable probe_prior() {
  CostTable t = zcube_loop_seconds(cpu_model("i80386"));
  t.far_lines = 100e-9;
  t.records_fetched = 100e-9;
  t.distant_lines = 100e-9;
  return t;
}

// One block's loops, solved for the block's groups: each loop's time less its groups measured
// before (`k` where `known`), divided among the block's own groups (non-negative least squares on
// relative errors). With `alone` (the multipliers rank 0 found timing the loops alone), a block of
// several groups is solved for one common slowdown s over the alone split (k = s x alone): timed
// at once, the ranks' shared memory system made the z-buffer's split unsteady (two probes: a
// fragment 1.05 and 0.47 ns) while its sum on the probe's loops was steady. Returns s (1 when
// free).
double solve_block(std::size_t b, const std::vector<Loop>& loops,
                   const std::vector<std::vector<double>>& A, const std::vector<double>& alone,
                   std::vector<double>& k, std::vector<bool>& known) {
  const auto& gs = blocks()[b].groups;
  double alone_sum = 0;
  for (std::size_t g : gs)
    alone_sum += alone.empty() ? 0.0 : alone[g];
  const bool common = gs.size() > 1 && alone_sum > 0;
  Matrix M;
  std::vector<double> r;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (loops[i].block != b) continue;
    double rest = loops[i].seconds;
    std::vector<double> row;
    double at_alone = 0; // the block's groups priced at the alone multipliers
    for (std::size_t g = 0; g < kGroups; ++g) {
      const bool mine = std::find(gs.begin(), gs.end(), g) != gs.end();
      if (known[g])
        rest -= k[g] * A[i][g];
      else if (mine && common)
        at_alone += alone[g] * A[i][g];
      else if (mine)
        row.push_back(A[i][g] / loops[i].seconds);
      else if (A[i][g] > 0)
        throw std::logic_error("probe loop '" + loops[i].name + "' runs group " +
                               probe_groups()[g].name + " before it is measured");
    }
    if (common) row.push_back(at_alone / loops[i].seconds);
    M.push_back(row);
    r.push_back(rest / loops[i].seconds);
  }
  if (M.empty())
    throw std::logic_error(std::string("probe block without loop: ") + blocks()[b].name);
  const std::vector<double> x = nnls(M, r);
  // A core that shares the memory system and the last-level cache with busy ones is no faster
  // than alone: at once, a group's cost is floored at its alone cost (the fit's slowdown, returned,
  // may come out below 1; the noise of the subtraction chain made it 0.81-0.99 for the near
  // z-buffer in probes whose loops took the same median time at once as alone).
  const bool floored = !alone.empty();
  for (std::size_t j = 0; j < gs.size(); ++j) {
    const double fitted = common ? x[0] * alone[gs[j]] : x[j];
    k[gs[j]] = floored ? std::max(fitted, alone[gs[j]]) : fitted;
    known[gs[j]] = true;
  }
  return common ? x[0] : 1.0;
}

// Solves the blocks in order (solve_block). Returns one multiplier a group on the prior table and
// writes every loop's fitted prediction into `log`.
std::vector<double> solve(const std::vector<Loop>& loops, const std::vector<double>& alone,
                          nlohmann::json& log) {
  const CostTable prior = probe_prior();
  std::vector<double> k(kGroups, 0.0);
  std::vector<bool> known(kGroups, false);
  std::vector<std::vector<double>> A;
  for (const Loop& l : loops)
    A.push_back(group_seconds(prior, probe_groups(), l.c));
  nlohmann::json slowdown = nlohmann::json::object();
  for (std::size_t b = 0; b < blocks().size(); ++b) {
    const double s = solve_block(b, loops, A, alone, k, known);
    if (blocks()[b].groups.size() > 1 && !alone.empty()) slowdown[blocks()[b].name] = s;
  }
  nlohmann::json rows = nlohmann::json::array(), groups = nlohmann::json::array(),
                 mult = nlohmann::json::object(), per_op = nlohmann::json::object();
  for (std::size_t i = 0; i < loops.size(); ++i) {
    double pred = 0;
    nlohmann::json by_group = nlohmann::json::object();
    for (std::size_t g = 0; g < kGroups; ++g) {
      pred += k[g] * A[i][g];
      if (A[i][g] > 0) by_group[probe_groups()[g].name] = A[i][g];
    }
    rows.push_back({{"loop", loops[i].name},
                    {"block", blocks()[loops[i].block].name},
                    {"seconds", loops[i].seconds},
                    {"calls", loops[i].calls},
                    {"counters", loops[i].c},
                    {"prior_s", by_group},
                    {"predicted_s", pred}});
  }
  for (std::size_t g = 0; g < kGroups; ++g) {
    groups.push_back({{"group", probe_groups()[g].name}, {"fields", probe_groups()[g].fields}});
    mult[probe_groups()[g].name] = k[g];
  }
  CostTable prior_t = prior;
  for (auto& [id, v] : prior_t.fields())
    per_op[id.substr(5)] = *v;
  // The loops (each its counters, time, the prior's seconds a group and the fitted prediction),
  // the groups, the prior table (seconds an operation on the 80386) and each group's multiplier on
  // it: what scripts/probe_instructions.py re-solves on instruction counts.
  log = {{"loops", rows},
         {"groups", groups},
         {"prior_i386_s", per_op},
         {"multipliers", mult},
         {"slowdown_over_alone", slowdown}};
  return k;
}

} // namespace

CpuProbe measure_cpu(const std::string& root, double min_seconds, const ProbeRanks& ranks) {
  premap_heap(std::size_t(1) << 30);
  Probe p{min_seconds, ranks, {}, {}, {}};
  // The bone's 78,738 triangles (a dense mesh as the bunny's, on no workload) at the workloads'
  // sizes and triangle sizes: 512 and 1024 (elastic's bunny at 1024x1024: 2-4 rows and 2 pixels a
  // span), 2048 and 4096 (Kurc's bunny at 5120x5120: 20 rows, 8 pixels a span; a frame buffer of
  // hundreds of megabytes). The thesis's 16 spheres: Blazek's triangles at the workload's size.
  // The bone shuffled: the z-buffer's far lines of a scanned mesh listed without locality (the
  // bunny's file). The bands: the z-buffer without far lines, the spheres' (a triangle a pixel or
  // less) and Figure 9's cubes (spans of hundreds of pixels) beside the bone's; whole pictures
  // then price the far lines alone. MultiScatter's triangle records: the bone's triangles among
  // 1 and 2 nodes. Three bones overlapping, and a pair's node's half of the triangles: the active
  // z-buffer's tested and appended pixels in other proportions than the bone's.
  render_loops(p, load(root + "/scenes/bone.json", 512), false);
  render_loops(p, load(root + "/scenes/bone.json", 1024), false);
  render_loops(p, load(root + "/scenes/bone.json", 2048), false);
  render_loops(p, load(root + "/scenes/bone.json", 4096), true);
  active_loops(p, load(root + "/scenes/bone.json", 4096), false);
  active_loops(p, load(root + "/scenes/bones.json", 2048), true);
  for (int size : {512, 1024, 2048, 4096})
    near_loops(p, load(root + "/scenes/bone.json", size));
  near_loops(p, load(root + "/scenes/blazek/thesis_spheres_16.json", 512));
  near_loops(p, load(root + "/scenes/blazek_fig9.sdl", 4096));
  multiscatter_loops(p, load(root + "/scenes/bone.json", 1024), 1);
  multiscatter_loops(p, load(root + "/scenes/bone.json", 1024), 2);
  sphere_loops(p, load(root + "/scenes/blazek/thesis_spheres_16.json", 512));
  buffer_loops(p, 4096, true);
  buffer_loops(p, 5120, false);
  // Every loop recorded in block order, so a block's loops come after those it subtracts.
  const auto by_block = [](const Loop& a, const Loop& b) { return a.block < b.block; };
  std::stable_sort(p.loops.begin(), p.loops.end(), by_block);
  std::stable_sort(p.loops_alone.begin(), p.loops_alone.end(), by_block);
  CpuProbe out;
  if (!p.loops_alone.empty()) {
    const std::vector<double> k = solve(p.loops_alone, {}, out.alone_log);
    out.alone = {scale_groups(probe_prior(), probe_groups(), k), k};
  }
  // At once, a block of several groups keeps the split rank 0 found alone (solve_block).
  const std::vector<double> alone = ranks.share(out.alone.multipliers);
  const std::vector<double> k = solve(p.loops, alone, out.at_once_log);
  out.at_once = {scale_groups(probe_prior(), probe_groups(), k), k};
  return out;
}

} // namespace zc
