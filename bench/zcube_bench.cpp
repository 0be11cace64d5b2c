// Host renderer throughput (a benchmark, never a test): triangles/s and pixels/s of the reference
// renderer (zc::render_scene) for the teapot, the bone iso-surface and the bunny at 512x512 and
// 3840x2160, on one thread and on every core, side by side with Mesa's llvmpipe drawing the same
// triangles (same world-space positions and view-projection matrix, same size, depth test LESS,
// same culling) with LP_NUM_THREADS = 1 and the core count, when the GL harness is built.
//   usage: zcube_bench [--quick] [--no-gl] [--scene teapot|bone|bunny] [--size WxH]
//                      [--threads N] [--min-seconds S] [--frames F] [--digest] [--cpu-time]
//                      [--pairs P]
// Every case repeats until at least S seconds (default 0.3) and reports the median frame time;
// --frames F draws exactly F timed frames instead (repeatable instruction counts for a profiler);
// --digest prints a hash of each case's colours, depths, ids and counters (renderers compared);
// --cpu-time times the frames (zcube's and llvmpipe's) in CPU time of their process (all threads)
// instead of wall time: on a loaded machine, one thread's figure then leaves out the time other
// programs ran (with several threads it is work, not latency); --pairs P runs zcube and llvmpipe
// alternately P times a case and reports the medians and the median of the P ratios.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "raster/renderer.hpp"
#include "scene/load.hpp"
#ifdef ZCUBE_GL_HARNESS
#include "gl_harness.hpp"
#endif

using namespace zc;

namespace {

bool g_cpu_time = false; // --cpu-time

double now_s() {
  if (g_cpu_time) {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Median time of one frame. Frames go into one reused frame buffer (render_scene_into: what
// render_scene does, minus allocating a new image each time), as llvmpipe reuses its FBO.
// FNV-1a over bytes: a digest to compare two renderers' outputs, not a cryptographic hash.
std::uint64_t fnv1a(const void* p, std::size_t n, std::uint64_t h = 14695981039346656037ull) {
  for (std::size_t i = 0; i < n; ++i)
    h = (h ^ static_cast<const unsigned char*>(p)[i]) * 1099511628211ull;
  return h;
}

std::uint64_t digest(const Framebuffer& fb, const Counters& c) {
  std::uint64_t h = fnv1a(fb.rgb().data(), fb.rgb().size());
  h = fnv1a(fb.depth().data(), fb.depth().size() * sizeof(float), h);
  h = fnv1a(fb.ids().data(), fb.ids().size() * sizeof(std::uint32_t), h);
  return fnv1a(&c, sizeof c, h);
}

double median_render(const Scene& s, int threads, double min_s, int frames, Counters& counters,
                     std::uint64_t* hash) {
  Framebuffer fb;
  counters = render_scene_into(s, threads, fb); // warm-up, sizes the frame buffer
  std::vector<double> t;
  const double start = now_s();
  while (frames > 0 ? int(t.size()) < frames : (t.size() < 3 || now_s() - start < min_s)) {
    const double t0 = now_s();
    counters = render_scene_into(s, threads, fb);
    t.push_back(now_s() - t0);
  }
  std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
  if (hash) *hash = digest(fb, counters);
  return t[t.size() / 2];
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

std::string cpu_model() {
  std::ifstream f("/proc/cpuinfo");
  for (std::string line; std::getline(f, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

#ifdef ZCUBE_GL_HARNESS
// The same triangles for GL: world-space positions, each vertex's Gouraud light times the colour
// of the material of a triangle that uses it, and zcube's view-projection matrix.
bench::GlScene gl_scene(const Scene& s) {
  const View v = make_view(s);
  bench::GlScene g;
  g.width = s.width;
  g.height = s.height;
  g.cull_back = s.cull == CullMode::Back;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      g.view_proj[4 * c + r] = float(v.view_proj[c][r]);
  std::vector<std::uint32_t> mat(s.vertices.size(), 0);
  for (const auto& t : s.triangles)
    for (std::uint32_t k : t.v)
      mat[k] = t.material;
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    const ProjectedVertex p = v.project(s.vertices[i]);
    const glm::vec3 kd = s.materials[mat[i]].kd;
    for (int k = 0; k < 3; ++k) {
      g.position.push_back(s.vertices[i].position[k]);
      g.color.push_back(p.light[k] * kd[k]);
    }
  }
  for (const auto& t : s.triangles)
    g.index.insert(g.index.end(), t.v, t.v + 3);
  return g;
}
#endif

} // namespace

int main(int argc, char** argv) {
  bool quick = false, gl = true, want_digest = false;
  double min_s = 0.3;
  int frames = 0, only_threads = 0, only_w = 0, only_h = 0, pairs = 1;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick")
      quick = true;
    else if (a == "--no-gl")
      gl = false;
    else if (a == "--digest")
      want_digest = true;
    else if (a == "--cpu-time")
      g_cpu_time = true;
    else if (a == "--scene" && i + 1 < argc)
      only = argv[++i];
    else if (a == "--min-seconds" && i + 1 < argc)
      min_s = std::atof(argv[++i]);
    else if (a == "--pairs" && i + 1 < argc)
      pairs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--frames" && i + 1 < argc)
      frames = std::max(1, std::atoi(argv[++i]));
    else if (a == "--threads" && i + 1 < argc)
      only_threads = std::max(1, std::atoi(argv[++i]));
    else if (a == "--size" && i + 1 < argc &&
             std::sscanf(argv[i + 1], "%dx%d", &only_w, &only_h) == 2 && only_w > 0 && only_h > 0)
      ++i;
    else {
      std::fprintf(stderr, "usage: zcube_bench [--quick] [--no-gl] [--scene teapot|bone|bunny] "
                           "[--size WxH] [--threads N] [--min-seconds S] [--frames F] "
                           "[--digest] [--cpu-time] [--pairs P]\n");
      return 2;
    }
  }
#ifndef ZCUBE_GL_HARNESS
  if (gl)
    std::printf("llvmpipe: not compared (zcube_bench was built without EGL/GL: install libegl-dev "
                "libgl-dev libegl-mesa0 libgl1-mesa-dri and re-run cmake)\n");
  gl = false;
#endif
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  std::printf("host: %s, %d hardware threads; median of >= %.2f s per case\n", cpu_model().c_str(),
              cores, min_s);
  const std::string root = ZCUBE_SOURCE_DIR;
  const std::vector<std::pair<std::string, std::string>> scenes = {
      {"teapot", root + "/scenes/teapot.json"},
      {"bone", root + "/scenes/bone.json"},
      {"bunny", root + "/scenes/bunny.json"}};
  std::vector<std::pair<int, int>> sizes = {{512, 512}, {3840, 2160}};
  if (quick) sizes.resize(1);
  if (only_w > 0) sizes = {{only_w, only_h}};
  std::vector<int> thread_counts = {1};
  if (cores > 1) thread_counts.push_back(cores);
  if (only_threads > 0) thread_counts = {only_threads};

  std::printf("%-7s %-10s %3s %10s %10s %10s %10s %7s %7s %8s\n", "scene", "size", "thr",
              "zc Mtri/s", "zc Mpix/s", "lp Mtri/s", "lp Mpix/s", "tri x", "pix x", "lp/zc px");
  for (const auto& [name, path] : scenes) {
    if (!only.empty() && name != only) continue;
    for (auto [w, h] : sizes) {
      LoadOptions lo;
      lo.width = w;
      lo.height = h;
      const Scene s = load_scene(path, lo);
#ifdef ZCUBE_GL_HARNESS
      bench::GlScene gs;
      if (gl) gs = gl_scene(s);
#endif
      const double tris = double(s.triangles.size());
      for (int threads : thread_counts) {
        Counters c;
        std::uint64_t hash = 0;
        // --pairs P: zcube and llvmpipe alternately P times; the medians, and the median ratio.
        std::vector<double> zt, lt, ratio;
#ifdef ZCUBE_GL_HARNESS
        bench::GlResult g;
#endif
        for (int r = 0; r < pairs; ++r) {
          zt.push_back(median_render(s, threads, min_s, frames, c, want_digest ? &hash : nullptr));
#ifdef ZCUBE_GL_HARNESS
          if (!gl) continue;
          g = bench::gl_time_frame(gs, threads, min_s, g_cpu_time);
          if (!g.ok) break;
          lt.push_back(g.seconds);
          ratio.push_back(g.seconds / zt.back());
#endif
        }
        const double t = median(zt);
        const double px = double(c.pixels_generated);
        std::printf("%-7s %4dx%-5d %3d %10.3f %10.2f", name.c_str(), w, h, threads, tris / t / 1e6,
                    px / t / 1e6);
        if (want_digest) std::printf(" digest %016llx", static_cast<unsigned long long>(hash));
#ifdef ZCUBE_GL_HARNESS
        if (gl) {
          if (g.ok) {
            const double lpx = double(g.fragments), lt_med = median(lt), x = median(ratio);
            std::printf(" %10.3f %10.2f %7.2f %7.2f %8.4f   [%s]\n", tris / lt_med / 1e6,
                        lpx / lt_med / 1e6, x, x * px / lpx, lpx / px, g.renderer.c_str());
          } else {
            std::printf("   llvmpipe failed: %s\n", g.error.c_str());
          }
          std::fflush(stdout);
          continue;
        }
#endif
        std::printf("\n");
        std::fflush(stdout);
      }
    }
  }
  if (gl)
    std::printf("tri x, pix x: zcube's triangles/s and pixels/s over llvmpipe's (LP_NUM_THREADS = "
                "thr) on the same triangles; > 1: zcube is faster. Pixels are fragments "
                "rasterised (zcube: pixels generated; llvmpipe: GL_SAMPLES_PASSED with no depth "
                "test), lp/zc px their ratio.\n");
  return 0;
}
