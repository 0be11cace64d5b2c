// Host renderer throughput (a benchmark, never a test): triangles/s and pixels/s of
// zc::render_scene for the teapot, the bone iso-surface and the bunny at 512x512 and 3840x2160,
// on one thread and on every core, side by side with Mesa's llvmpipe drawing the same projected
// triangles (LP_NUM_THREADS = 1 and the core count) when the GL harness is built.
//   usage: zcube_bench [--quick] [seconds per case]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "raster/renderer.hpp"
#include "scene/load.hpp"
#ifdef ZCUBE_GL_HARNESS
#include "gl_harness.hpp"
#endif

using namespace zc;

// Median time of one frame into a reused frame buffer (as llvmpipe reuses its render target).
static double median_render(const Scene& s, int threads, double min_s, RenderResult* last) {
  std::vector<double> t;
  const auto start = std::chrono::steady_clock::now();
  while (t.size() < 3 ||
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < min_s) {
    const auto t0 = std::chrono::steady_clock::now();
    last->counters = render_scene_into(s, threads, last->image);
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
  return t[t.size() / 2];
}

int main(int argc, char** argv) {
  bool quick = false;
  double min_s = 0.3;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else
      min_s = std::atof(argv[i]);
  }
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  const std::string root = ZCUBE_SOURCE_DIR;
  const std::vector<std::pair<std::string, std::string>> scenes = {
      {"teapot", root + "/scenes/teapot.json"},
      {"bone", root + "/scenes/bone.json"},
      {"bunny", root + "/scenes/bunny.json"}};
  std::vector<std::pair<int, int>> sizes = {{512, 512}, {3840, 2160}};
  if (quick) sizes.resize(1);
  std::printf("%-7s %-10s %3s %12s %12s %12s %12s %8s %8s\n", "scene", "size", "thr", "zc Mtri/s",
              "zc Mpix/s", "lp Mtri/s", "lp Mpix/s", "tri x", "pix x");
  for (const auto& [name, path] : scenes)
    for (auto [w, h] : sizes) {
      LoadOptions lo;
      lo.width = w;
      lo.height = h;
      const Scene s = load_scene(path, lo);
#ifdef ZCUBE_GL_HARNESS
      const View v = make_view(s);
      std::vector<ProjectedVertex> pv;
      for (const auto& vx : s.vertices)
        pv.push_back(v.project(vx));
      std::vector<std::uint32_t> idx;
      for (const auto& t : s.triangles)
        idx.insert(idx.end(), t.v, t.v + 3);
#endif
      for (int threads : {1, cores}) {
        RenderResult r;
        const double t = median_render(s, threads, min_s, &r);
        const double tris = double(s.triangles.size()), px = double(r.counters.pixels_generated);
        std::printf("%-7s %4dx%-5d %3d %12.2f %12.2f", name.c_str(), w, h, threads, tris / t / 1e6,
                    px / t / 1e6);
#ifdef ZCUBE_GL_HARNESS
        const auto g = bench::gl_time_frame(pv, idx, w, h, threads, min_s);
        if (g.ok)
          std::printf(" %12.2f %12.2f %8.2f %8.2f   [%s]\n", tris / g.seconds / 1e6,
                      px / g.seconds / 1e6, g.seconds / t, g.seconds / t, g.renderer.c_str());
        else
          std::printf("   llvmpipe: %s\n", g.error.c_str());
#else
        std::printf("   (built without the GL harness)\n");
#endif
        if (threads == cores && cores == 1) break;
      }
    }
  std::printf("tri x / pix x: zcube throughput over llvmpipe's on the same triangles (>1: zcube is "
              "faster). Pixels/s use zcube's pixels generated for both.\n");
  return 0;
}
