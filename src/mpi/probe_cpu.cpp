#include "mpi/probe_cpu.hpp"

#include <malloc.h>
#include <time.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "algo/elastic_partition.hpp"
#include "compositing/gather.hpp"
#include "raster/active_pixels.hpp"
#include "raster/renderer.hpp"
#include "raster/zbuffer.hpp"
#include "scene/load.hpp"
#include "scene/tessellate.hpp"
#include "util/nnls.hpp"

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

// Seconds per call of fn (the median of calls repeated for at least `min_s`); `prep` runs before
// each call, untimed.
template <class Prep, class F> double time_loop(Prep&& prep, F&& fn, double min_s) {
  std::vector<double> t;
  double total = 0;
  do {
    prep();
    const double t0 = cpu_now();
    fn();
    const double s = cpu_now() - t0;
    t.push_back(s);
    total += s;
  } while (total < min_s || t.size() < 3);
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}
template <class F> double time_loop(F&& fn, double min_s) {
  return time_loop([] {}, fn, min_s);
}

// The probe's cost groups: one multiplier each on the prior table (the 80386's physical estimate
// keeps the proportions inside a group); each has a loop that times it (nearly) alone.
const std::vector<CostGroup>& probe_groups() {
  static const std::vector<CostGroup> g = {
      {"vertex", {"vertices_transformed"}},
      {"triangle", {"triangles_in", "triangles_culled", "triangles_clipped", "triangles_setup"}},
      {"estimate", {"triangles_estimated"}},
      {"tessellate", {"triangles_tessellated"}},
      {"spans", {"spans", "rows_scanned"}},
      {"pixels",
       {"pixels_generated", "pixels_tested", "pixels_written", "pixels_final", "texels_fetched"}},
      {"clear", {"pixels_cleared"}},
      {"merge", {"merge_ops"}},
      {"packing", {"bytes_packed"}},
      {"list_merge", {"list_merges"}},                // timed by the active merge
      {"scanline", {"wpa_tested", "wpa_appended"}},  // timed by the active z-buffer
      {"edges", {"edge_walks"}},                     // timed by the z-buffers and span lists
      {"span_start", {"span_starts"}},               // timed by the z-buffers
      {"sort", {"sort_steps"}},                      // timed by the span lists
      {"records", {"records_packed"}}};              // timed by the sparse packing
  return g;
}

struct Fit {
  Matrix A;
  std::vector<double> b;
  nlohmann::json& log;
  double min_s;
  void add(const std::string& what, const Counters& c, double t) {
    A.push_back(group_seconds(prior_i386_costs(), probe_groups(), c));
    b.push_back(t);
    log.push_back({{"loop", what}, {"seconds", t}, {"counters", c}});
  }
};

// The renderer's loops on one scene at one size.
void render_loops(Fit& f, const std::string& path, int size) {
  LoadOptions lo;
  lo.width = lo.height = size;
  const Scene s = load_scene(path, lo);
  const std::string name = s.path.substr(s.path.find_last_of('/') + 1) + " " +
                           std::to_string(size) + "x" + std::to_string(size);
  const NodeRenderer nr(s);
  std::vector<ProjectedVertex> pv(s.vertices.size());
  Counters cv, ct, cz, cs, ca, ce;
  f.add("project " + name, cv,
        time_loop(
            [&] {
              cv = Counters{};
              for (std::size_t i = 0; i < pv.size(); ++i)
                pv[i] = nr.project(s.vertices[i], cv);
            },
            f.min_s));
  auto setup = [&](std::size_t i, TriangleBatch& batch, Counters& c) {
    nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, batch, c);
  };
  TriangleBatch one;
  f.add("set-up " + name, ct,
        time_loop(
            [&] {
              ct = Counters{};
              for (std::size_t i = 0; i < s.triangles.size(); ++i) {
                one.clear();
                setup(i, one, ct);
              }
            },
            f.min_s));
  // The sequential z-buffer of a slice (elastic, Blazek): set-up and scan conversion.
  Framebuffer fb = nr.make_framebuffer(RowSet::all(size));
  f.add("z-buffer " + name, cz,
        time_loop([&] { fb.clear(nr.background()); },
                  [&] {
                    cz = Counters{};
                    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
                      one.clear();
                      setup(i, one, cz);
                      draw_batch(one, nr.shade(), fb, cz);
                    }
                  },
                  f.min_s));
  // Kurc et al.'s span lists and modified scanline z-buffer.
  TriangleBatch all;
  Counters ignored;
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    setup(i, all, ignored);
  SpanLists lists;
  f.add("span lists " + name, cs,
        time_loop(
            [&] {
              cs = Counters{};
              lists = build_span_lists(all, size, size, cs);
            },
            f.min_s));
  ActivePixels wpa;
  f.add("active z-buffer " + name, ca,
        time_loop(
            [&] {
              ca = Counters{};
              wpa = zbuffer_spans(lists, all, nr.shade(), size, ca);
            },
            f.min_s));
  // Charles et al.'s load estimate: row extents, a difference array, a scan.
  std::vector<RowExtent> ext(s.triangles.size());
  f.add("load estimate " + name, ce,
        time_loop(
            [&] {
              ce = Counters{};
              for (std::size_t i = 0; i < s.triangles.size(); ++i) {
                const Triangle& t = s.triangles[i];
                const ProjectedVertex* p3[3] = {&pv[t.v[0]], &pv[t.v[1]], &pv[t.v[2]]};
                if (!row_extent(p3, size, size, ext[i].y0, ext[i].y1)) ext[i] = {1, 0};
              }
              const auto rows = scan_load(load_differences(ext, size), size);
              ce.triangles_estimated = s.triangles.size();
              ce.rows_scanned = rows.size();
            },
            f.min_s));
  // Merges and packing on this picture's active pixels: two halves of the rows' pixels.
  ActivePixels odd = select_rows(wpa, [](int y) { return y % 2; });
  ActivePixels even = select_rows(wpa, [](int y) { return y % 2 == 0; });
  Counters cm;
  f.add("active merge " + name, cm,
        time_loop(
            [&] {
              cm = Counters{};
              (void)merge_active(odd, even, cm);
            },
            f.min_s));
  Counters cp;
  f.add("sparse packing " + name, cp,
        time_loop(
            [&] {
              cp = Counters{};
              cp.bytes_packed = serialize_sparse(wpa).size();
              cp.records_packed = wpa.count();
            },
            f.min_s));
  // The picture pasted from them (Kurc et al.'s output on node 0: compositing::paste).
  const std::vector<Message> parts{uncharged(serialize_sparse(wpa))};
  Framebuffer picture = nr.make_framebuffer(RowSet::all(size));
  Counters cu;
  f.add("sparse paste " + name, cu,
        time_loop(
            [&] {
              cu = Counters{};
              compositing::paste(parts, picture, size, cu);
            },
            f.min_s));
}

// Frame buffers: a new one (allocation and clear: what make_framebuffer costs), locations
// packed into a message and merged back (the full z-buffer merges).
void buffer_loops(Fit& f, int width, int height) {
  const std::string name = std::to_string(width) + "x" + std::to_string(height);
  Counters cc;
  cc.pixels_cleared = std::uint64_t(width) * height;
  f.add("new frame buffer " + name, cc,
        time_loop([&] { Framebuffer fb(width, RowSet::all(height), glm::vec3(0)); }, f.min_s));
  Framebuffer a(width, RowSet::all(height), glm::vec3(0)), b = a;
  for (std::size_t i = 0; i < b.depth().size(); i += 3) {
    b.depth()[i] = float(i % 7) * 0.1f;
    b.ids()[i] = std::uint32_t(i);
  }
  Counters cp;
  std::vector<std::uint8_t> msg;
  f.add("location packing " + name, cp,
        time_loop(
            [&] {
              msg = b.pack_locations(0, b.pixel_count());
              cp.bytes_packed = msg.size();
            },
            f.min_s));
  Counters cm;
  f.add("location merge " + name, cm,
        time_loop(
            [&] {
              cm = Counters{};
              cm.merge_ops = a.merge_locations(msg, 0);
            },
            f.min_s));
}

void tessellation_loop(Fit& f, const std::string& path) {
  LoadOptions lo;
  const Scene s = load_scene(path, lo);
  Counters c;
  f.add("tessellate " + s.path.substr(s.path.find_last_of('/') + 1), c,
        time_loop(
            [&] {
              c = Counters{};
              for (const ObjectDesc& d : s.objects)
                if (d.kind != "mesh") c.triangles_tessellated += tessellate(d).triangles.size();
            },
            f.min_s));
}

} // namespace

CostTable measure_cpu(const std::string& root, double min_seconds, nlohmann::json& log) {
  premap_heap(std::size_t(1) << 30);
  Fit f{{}, {}, log, min_seconds};
  // Sizes of the validation workloads' order (frame buffers of tens to hundreds of megabytes,
  // beyond the caches), other scenes.
  render_loops(f, root + "/scenes/teapot.json", 1024);
  render_loops(f, root + "/scenes/teapot.json", 3072);
  render_loops(f, root + "/scenes/newell_teapot.json", 2048);
  // A dense mesh (78,738 triangles: long span lists, few pixels a span), at two sizes.
  render_loops(f, root + "/scenes/bone.json", 1024);
  render_loops(f, root + "/scenes/bone.json", 4096);
  buffer_loops(f, 2048, 2048);
  buffer_loops(f, 4096, 4096);
  tessellation_loop(f, root + "/scenes/blazek/thesis_spheres_16.json");
  // Relative errors, and a weak pull of each multiplier towards the overall ratio (a group no loop
  // exercises, texels here, keeps the table's proportions).
  const std::size_t G = probe_groups().size(), rows = f.A.size();
  double ta = 0, tb = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    for (double v : f.A[r])
      ta += v;
    tb += f.b[r];
  }
  const double k0 = ta > 0 ? tb / ta : 1.0;
  Matrix A = f.A;
  std::vector<double> b = f.b;
  for (std::size_t r = 0; r < rows; ++r) {
    for (double& v : A[r])
      v /= f.b[r];
    b[r] = 1.0;
  }
  for (std::size_t g = 0; g < G; ++g) {
    std::vector<double> line(G, 0.0);
    line[g] = 0.01 / k0;
    A.push_back(line);
    b.push_back(0.01);
  }
  const std::vector<double> k = nnls(A, b);
  for (std::size_t r = 0; r < rows; ++r) {
    double p = 0;
    for (std::size_t g = 0; g < G; ++g)
      p += f.A[r][g] * k[g];
    log[r]["predicted_s"] = p;
  }
  return scale_groups(prior_i386_costs(), probe_groups(), k);
}

} // namespace zc
