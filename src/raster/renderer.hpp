#pragma once
// The reference renderer: every algorithm's image is compared byte for byte with this one.
#include <cstdint>
#include <functional>
#include <vector>

#include "raster/framebuffer.hpp"
#include "raster/setup.hpp"
#include "raster/shade.hpp"
#include "raster/view.hpp"
#include "scene/scene.hpp"
#include "util/counters.hpp"

namespace zc {

class SetupCache;

// The per-node rendering toolkit the parallel algorithms use: a view, the scene's materials and
// textures, and set-up of triangles whose projected vertices the caller supplies.
class NodeRenderer {
public:
  explicit NodeRenderer(const Scene& scene);
  NodeRenderer(const Scene& scene, const Camera& camera); // another frame's camera
  // The same with the scene's bounds already known (scene_bounds): no pass over its vertices.
  NodeRenderer(const Scene& scene, const Camera& camera, const Bounds& bounds);

  const View& view() const { return view_; }
  const ShadeContext& shade() const { return shade_; }
  int width() const { return view_.width; }
  int height() const { return view_.height; }
  glm::vec3 background() const { return background_; }
  bool cull_back() const { return cull_back_; }

  ProjectedVertex project(const Vertex& v, Counters& c) const {
    ++c.vertices_transformed;
    return view_.project(v);
  }

  // Sets up triangle `id` (its record `tri`): its projected vertices are pv[tri.v[k]] and, looked
  // up only when its material is textured, its texture coordinates uvs[tri.v[k]] (uvs: the scene's
  // texture coordinates or a copy indexed the same way; nullptr for an untextured scene).
  void setup(std::uint32_t id, const Triangle& tri, const ProjectedVertex* pv, const glm::vec2* uvs,
             TriangleBatch& out, Counters& c) const {
    const ProjectedVertex* const p[3] = {&pv[tri.v[0]], &pv[tri.v[1]], &pv[tri.v[2]]};
    setup_projected(id, tri, p, uvs, out, c);
  }
  // The same when the caller has looked up the projected vertices, p[0..2]: from this process's
  // set-up cache when it holds the triangle (raster/setup_cache.hpp), else computed.
  void setup_projected(std::uint32_t id, const Triangle& tri, const ProjectedVertex* const p[3],
                       const glm::vec2* uvs, TriangleBatch& out, Counters& c) const {
    if (setup_cache_ && cached_setup(id, tri, p, out, c)) return;
    compute_setup(id, tri, p, uvs, out, c);
  }
  // Rows [y0, y1] triangle `id` can touch from its projected vertices p[0..2] (row_extent).
  bool rows(std::uint32_t id, const ProjectedVertex* const p[3], int& y0, int& y1) const {
    if (setup_cache_) return cached_rows(id, p, y0, y1);
    return row_extent(p, view_.width, view_.height, y0, y1);
  }
  bool has_setup_cache() const { return setup_cache_ != nullptr; }

  Framebuffer make_framebuffer(const RowSet& rows) const {
    return Framebuffer(view_.width, rows, background_);
  }

private:
  bool cached_setup(std::uint32_t id, const Triangle& tri, const ProjectedVertex* const p[3],
                    TriangleBatch& out, Counters& c) const;
  bool cached_rows(std::uint32_t id, const ProjectedVertex* const p[3], int& y0, int& y1) const;
  void compute_setup(std::uint32_t id, const Triangle& tri, const ProjectedVertex* const p[3],
                     const glm::vec2* uvs, TriangleBatch& out, Counters& c) const;

  View view_;
  ShadeContext shade_;
  glm::vec3 background_;
  bool cull_back_;
  const SetupCache* setup_cache_; // this process's set-up of the scene, if it holds one
};

struct RenderResult {
  Framebuffer image;
  Counters counters;
  double wall_time_s = 0;
};

// Renders the whole scene on `threads` host threads (1 = the sequential reference). Threads own
// interleaved bands of rows (no lock per pixel; Malerich's data-parallel variant), so the image
// and the counters are identical for every thread count.
RenderResult render_scene(const Scene& scene, int threads = 1);
// The same into `image` (resized on first use, then only cleared): for repeated frames.
Counters render_scene_into(const Scene& scene, int threads, Framebuffer& image);

} // namespace zc
