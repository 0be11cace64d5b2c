#include "raster/renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>

#include "raster/setup_cache.hpp"
#include "raster/worker_pool.hpp"
#include "raster/zbuffer.hpp"
#include "util/block_split.hpp"

namespace zc {

NodeRenderer::NodeRenderer(const Scene& scene) : NodeRenderer(scene, scene.camera) {}

NodeRenderer::NodeRenderer(const Scene& scene, const Camera& camera)
    : NodeRenderer(scene, camera, scene_bounds(scene)) {}

NodeRenderer::NodeRenderer(const Scene& scene, const Camera& camera, const Bounds& bounds)
    : view_(make_view(scene, camera, bounds)), shade_(ShadeContext::of(scene)),
      background_(scene.background), cull_back_(scene.cull == CullMode::Back),
      setup_cache_(find_setup_cache(scene, view_, cull_back_)) {}

bool NodeRenderer::cached_setup(std::uint32_t id, const Triangle& tri,
                                const ProjectedVertex* const p[3], TriangleBatch& out,
                                Counters& c) const {
  return setup_cache_->setup(id, tri.material, p, out, c);
}

void NodeRenderer::compute_setup(std::uint32_t id, const Triangle& tri,
                                 const ProjectedVertex* const p[3], const glm::vec2* uvs,
                                 TriangleBatch& out, Counters& c) const {
  SetupInput in{{p[0], p[1], p[2]}, {nullptr, nullptr, nullptr}, id, tri.material};
  if (shade_.textures && uvs && (*shade_.materials)[tri.material].texture >= 0)
    for (int k = 0; k < 3; ++k)
      in.uv[k] = &uvs[tri.v[k]];
  setup_triangle(in, view_.width, view_.height, cull_back_, out, c);
}

bool NodeRenderer::cached_rows(std::uint32_t id, const ProjectedVertex* const p[3], int& y0,
                               int& y1) const {
  const SetupCache::Rows cached = setup_cache_->rows(id, p, y0, y1);
  if (cached != SetupCache::Rows::Unknown) return cached == SetupCache::Rows::Some;
  return row_extent(p, view_.width, view_.height, y0, y1);
}

namespace {

// A worker's screen triangles by band of rows: band k's are idx[start[k] .. start[k + 1]), in the
// order they were set up (so every pixel sees its triangles in scene order, as on one thread).
struct BandBins {
  std::vector<std::uint32_t> start, idx;
  std::vector<std::uint32_t> first, last; // each triangle's first and last band, noted at set-up

  void clear() {
    first.clear();
    last.clear();
  }
  // Notes the bands of the triangles set up since the last call (read while still in cache).
  void note(const TriangleBatch& b, int band_h) {
    for (std::size_t i = first.size(); i < b.tris.size(); ++i) {
      first.push_back(std::uint32_t(b.tris[i].ymin / band_h));
      last.push_back(std::uint32_t(b.tris[i].ymax / band_h));
    }
  }
  void fill(int bands) {
    start.assign(std::size_t(bands) + 1, 0);
    for (std::size_t i = 0; i < first.size(); ++i)
      for (std::uint32_t k = first[i]; k <= last[i]; ++k)
        ++start[k + 1];
    for (int k = 0; k < bands; ++k)
      start[k + 1] += start[k];
    idx.resize(start[bands]);
    std::vector<std::uint32_t> at(start.begin(), start.end() - 1);
    for (std::uint32_t i = 0; i < first.size(); ++i)
      for (std::uint32_t k = first[i]; k <= last[i]; ++k)
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

// Rows per band. A band's colours, depths and ids (11 bytes a pixel) fit a core's L2 cache with
// room for its triangles, so the band is cleared and then drawn while it stays in cache: at
// 3840x2160 a frame buffer drawn triangle by triangle in one pass (91 MB) misses the L2 on every
// span. Several threads take bands in turn, at least 8 bands a thread for balance.
int band_rows(int width, int height, int threads) {
  constexpr std::size_t kBandBytes = std::size_t(1) << 19;
  const std::size_t row_bytes = std::size_t(std::max(1, width)) * Framebuffer::kLocationBytes;
  int h = int(std::max<std::size_t>(4, kBandBytes / row_bytes));
  if (threads > 1) h = std::min(h, std::max(4, height / (threads * 8)));
  return std::max(1, std::min(h, height));
}

// One worker's counters and covered pixels, a cache line of its own (no false sharing between
// threads that bump them once a triangle).
struct alignas(64) WorkerTally {
  Counters c;
  std::uint64_t covered = 0; // pixels written first by some triangle (TPF without a scan)
};

// A frame buffer of the right shape is cleared band by band by the threads that draw the bands
// (with the first chunk of triangles); any other is made anew, already clear. Returns whether the
// bands are to be cleared.
bool prepare_image(const Scene& scene, const NodeRenderer& nr, Framebuffer& image) {
  bool clear_bands = image.width() == scene.width && image.rows().begin == 0 &&
                     image.rows().stride == 1 && image.rows().end == scene.height;
  if (!clear_bands) {
    image = nr.make_framebuffer(RowSet::all(scene.height));
  } else if (scene.triangles.empty()) {
    image.clear(scene.background);
    clear_bands = false;
  }
  return clear_bands;
}

// Triangles set up and drawn a chunk at a time. One thread on a small frame buffer (a few L2
// caches' worth) sets up and draws a small chunk at a time, so its screen triangles (about 200
// bytes each) are drawn while still in cache and the frame buffer, revisited by every chunk,
// mostly stays there too. A large frame buffer, or several threads (two synchronisations a
// chunk), take large chunks: each chunk visits the bands again.
std::size_t chunk_triangles(const Scene& scene, int threads) {
  const std::size_t fb_bytes =
      std::size_t(scene.width) * std::size_t(scene.height) * Framebuffer::kLocationBytes;
  return threads == 1 && fb_bytes <= (std::size_t(4) << 20) ? 2048 : std::size_t(1) << 17;
}

// One band's rows drawn from every worker's set-up triangles (those binned to the band).
void draw_band(int band, int band_h, int bands, const std::vector<TriangleBatch>& batches,
               const std::vector<BandBins>& bins, const NodeRenderer& nr, const RowSet& rows,
               Framebuffer& image, Counters& c, std::uint64_t* covered) {
  for (std::size_t k = 0; k < batches.size(); ++k) {
    const TriangleBatch& b = batches[k];
    if (bands == 1) {
      for (const auto& t : b.tris)
        draw_triangle(t, b, nr.shade(), rows, image, c, covered);
      continue;
    }
    const BandBins& bin = bins[k];
    for (std::uint32_t j = bin.start[band]; j < bin.start[band + 1]; ++j) {
      const ScreenTriangle& t = b.tris[bin.idx[j]];
      draw_triangle(t, b, nr.shade(), rows, image, c, covered);
      // Bands are a host-side tiling, not the modelled program: a triangle's edges are set up
      // once, in its first band, whatever the band height and the thread count.
      if (band != t.ymin / band_h) --c.edge_walks;
    }
  }
}

Counters render_into(const Scene& scene, int threads, Framebuffer& image, RenderScratch& scratch) {
  threads = std::max(1, threads);
  const NodeRenderer nr(scene);
  const bool clear_bands = prepare_image(scene, nr, image);
  std::vector<WorkerTally> tally(threads);

  // 1. Vertex stage, contiguous chunks per thread.
  std::vector<ProjectedVertex>& pv = scratch.pv;
  pv.resize(scene.vertices.size());
  run_on_workers(threads, [&](int w) {
    const BlockRange mine = block_range(pv.size(), threads, w);
    for (std::size_t i = mine.begin; i < mine.end; ++i)
      pv[i] = nr.project(scene.vertices[i], tally[w].c);
  });

  // 2. Triangles in chunks: set-up split by triangle ranges, each worker's triangles binned by
  // band, rasterisation split by row bands.
  const glm::vec2* uvs = scene.uvs_if_textured();
  const int band_h = band_rows(scene.width, scene.height, threads);
  const int bands = (scene.height + band_h - 1) / band_h;
  const std::size_t chunk = chunk_triangles(scene, threads);
  std::vector<TriangleBatch>& batches = scratch.batches;
  batches.resize(threads);
  scratch.bins.resize(threads);
  for (std::size_t c0 = 0; c0 < scene.triangles.size(); c0 += chunk) {
    const std::size_t c1 = std::min(scene.triangles.size(), c0 + chunk);
    run_on_workers(threads, [&](int w) {
      TriangleBatch& b = batches[w];
      BandBins& bin = scratch.bins[w];
      b.clear();
      bin.clear();
      const BlockRange mine = block_range(c1 - c0, threads, w);
      for (std::size_t i = c0 + mine.begin; i < c0 + mine.end; ++i) {
        nr.setup(std::uint32_t(i), scene.triangles[i], pv.data(), uvs, b, tally[w].c);
        if (bands > 1) bin.note(b, band_h);
      }
      if (bands > 1) bin.fill(bands);
    });
    std::atomic<int> next{0};
    run_on_workers(threads, [&](int w) {
      for (int band; (band = next.fetch_add(1)) < bands;) {
        const RowSet rows =
            RowSet::band(band * band_h, std::min(scene.height, (band + 1) * band_h));
        if (clear_bands && c0 == 0) image.clear_rows(rows.begin, rows.end, scene.background);
        draw_band(band, band_h, bands, batches, scratch.bins, nr, rows, image, tally[w].c,
                  &tally[w].covered);
      }
    });
  }
  Counters total;
  for (const auto& t : tally)
    total += t.c;
  total.pixels_cleared = std::uint64_t(scene.width) * scene.height;
  total.pixels_final = 0;
  for (const auto& t : tally)
    total.pixels_final += t.covered;
  return total;
}

} // namespace

} // namespace zc
