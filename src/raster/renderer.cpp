#include "raster/renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include "raster/zbuffer.hpp"
#include "util/block_split.hpp"

namespace zc {

NodeRenderer::NodeRenderer(const Scene& scene) : NodeRenderer(scene, scene.camera) {}

NodeRenderer::NodeRenderer(const Scene& scene, const Camera& camera)
    : view_(make_view(scene, camera)), shade_(ShadeContext::of(scene)),
      background_(scene.background), cull_back_(scene.cull == CullMode::Back) {}

void NodeRenderer::setup_projected(std::uint32_t id, const Triangle& tri,
                                   const ProjectedVertex* const p[3], const glm::vec2* uvs,
                                   TriangleBatch& out, Counters& c) const {
  SetupInput in{{p[0], p[1], p[2]}, {nullptr, nullptr, nullptr}, id, tri.material};
  if (shade_.textures && uvs && (*shade_.materials)[tri.material].texture >= 0)
    for (int k = 0; k < 3; ++k)
      in.uv[k] = &uvs[tri.v[k]];
  setup_triangle(in, view_.width, view_.height, cull_back_, out, c);
}

namespace {

// Runs f(worker) on `n` workers (the calling thread is worker 0) and joins them.
template <class F> void run_workers(int n, F&& f) {
  std::vector<std::thread> ts;
  for (int w = 1; w < n; ++w)
    ts.emplace_back([&f, w] { f(w); });
  f(0);
  for (auto& t : ts)
    t.join();
}

// A worker's screen triangles by band of rows: band k's are idx[start[k] .. start[k + 1]), in the
// order they were set up (so every pixel sees its triangles in scene order, as on one thread).
struct BandBins {
  std::vector<std::uint32_t> start, idx;

  void fill(const TriangleBatch& b, int band_h, int bands) {
    start.assign(std::size_t(bands) + 1, 0);
    for (const auto& t : b.tris)
      for (int k = t.ymin / band_h; k <= t.ymax / band_h; ++k)
        ++start[k + 1];
    for (int k = 0; k < bands; ++k)
      start[k + 1] += start[k];
    idx.resize(start[bands]);
    std::vector<std::uint32_t> at(start.begin(), start.end() - 1);
    for (std::uint32_t i = 0; i < b.tris.size(); ++i)
      for (int k = b.tris[i].ymin / band_h; k <= b.tris[i].ymax / band_h; ++k)
        idx[at[k]++] = i;
  }
};

// What a frame needs besides the image, kept between the frames of render_scene_into.
struct RenderScratch {
  std::vector<ProjectedVertex> pv;
  std::vector<TriangleBatch> batches;
  std::vector<BandBins> bins;
};

Counters render_into(const Scene& scene, int threads, Framebuffer& image, RenderScratch& scratch);

} // namespace

RenderResult render_scene(const Scene& scene, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  RenderResult res;
  RenderScratch scratch;
  res.counters = render_into(scene, threads, res.image, scratch);
  res.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

Counters render_scene_into(const Scene& scene, int threads, Framebuffer& image) {
  thread_local RenderScratch scratch; // no allocation nor page fault for the next frame's buffers
  return render_into(scene, threads, image, scratch);
}

namespace {

Counters render_into(const Scene& scene, int threads, Framebuffer& image, RenderScratch& scratch) {
  threads = std::max(1, threads);
  const NodeRenderer nr(scene);
  // A frame buffer of the right shape is cleared band by band by the threads that draw the bands
  // (with the first chunk of triangles); any other is made anew, already clear.
  bool clear_bands = image.width() == scene.width && image.rows().begin == 0 &&
                     image.rows().stride == 1 && image.rows().end == scene.height;
  if (!clear_bands) {
    image = nr.make_framebuffer(RowSet::all(scene.height));
  } else if (scene.triangles.empty()) {
    image.clear(scene.background);
    clear_bands = false;
  }
  std::vector<Counters> tc(threads);
  // Pixels written first by some triangle, per thread: the covered pixels (TPF) without a scan.
  std::vector<std::uint64_t> covered(threads, 0);

  // 1. Vertex stage, contiguous chunks per thread.
  std::vector<ProjectedVertex>& pv = scratch.pv;
  pv.resize(scene.vertices.size());
  run_workers(threads, [&](int w) {
    const BlockRange mine = block_range(pv.size(), threads, w);
    for (std::size_t i = mine.begin; i < mine.end; ++i)
      pv[i] = nr.project(scene.vertices[i], tc[w]);
  });

  // 2. Triangles in chunks: set-up split by triangle ranges, each worker's triangles binned by
  // band, rasterisation split by row bands.
  const glm::vec2* uvs = scene.uvs_if_textured();
  const int band_h =
      threads == 1 ? std::max(1, scene.height) : std::max(4, scene.height / (threads * 8));
  const int bands = (scene.height + band_h - 1) / band_h;
  constexpr std::size_t kChunk = 1 << 16;
  std::vector<TriangleBatch>& batches = scratch.batches;
  batches.resize(threads);
  scratch.bins.resize(threads);
  for (std::size_t c0 = 0; c0 < scene.triangles.size(); c0 += kChunk) {
    const std::size_t c1 = std::min(scene.triangles.size(), c0 + kChunk);
    run_workers(threads, [&](int w) {
      TriangleBatch& b = batches[w];
      b.clear();
      const BlockRange mine = block_range(c1 - c0, threads, w);
      for (std::size_t i = c0 + mine.begin; i < c0 + mine.end; ++i)
        nr.setup(std::uint32_t(i), scene.triangles[i], pv.data(), uvs, b, tc[w]);
      if (bands > 1) scratch.bins[w].fill(b, band_h, bands);
    });
    std::atomic<int> next{0};
    run_workers(threads, [&](int w) {
      for (int band; (band = next.fetch_add(1)) < bands;) {
        const RowSet rows =
            RowSet::band(band * band_h, std::min(scene.height, (band + 1) * band_h));
        if (clear_bands && c0 == 0) image.clear_rows(rows.begin, rows.end, scene.background);
        for (int k = 0; k < threads; ++k) {
          const TriangleBatch& b = batches[k];
          if (bands == 1) {
            for (const auto& t : b.tris)
              draw_triangle(t, b, nr.shade(), rows, image, tc[w], &covered[w]);
            continue;
          }
          const BandBins& bin = scratch.bins[k];
          for (std::uint32_t j = bin.start[band]; j < bin.start[band + 1]; ++j) {
            const ScreenTriangle& t = b.tris[bin.idx[j]];
            draw_triangle(t, b, nr.shade(), rows, image, tc[w], &covered[w]);
            // The bands are host threads, not the modelled program: a triangle's edges are set
            // up once, in its first band, whatever the thread count.
            if (band != t.ymin / band_h) --tc[w].edge_walks;
          }
        }
      }
    });
  }
  Counters total;
  for (const auto& c : tc)
    total += c;
  total.pixels_cleared = std::uint64_t(scene.width) * scene.height;
  total.pixels_final = 0;
  for (std::uint64_t n : covered)
    total.pixels_final += n;
  return total;
}

} // namespace

} // namespace zc
