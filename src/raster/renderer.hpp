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

// The per-node rendering toolkit the parallel algorithms use: a view, the scene's materials and
// textures, and set-up of triangles whose projected vertices the caller supplies.
class NodeRenderer {
public:
  explicit NodeRenderer(const Scene& scene);
  NodeRenderer(const Scene& scene, const Camera& camera); // another frame's camera

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

  // Sets up triangle `id` (its record `tri`) with projected vertices pv[0..2] and, when the scene
  // is textured, texture coordinates uv[0..2].
  void setup(std::uint32_t id, const Triangle& tri, const ProjectedVertex* const pv[3],
             const glm::vec2* const uv[3], TriangleBatch& out, Counters& c) const;

  Framebuffer make_framebuffer(const RowSet& rows) const {
    return Framebuffer(view_.width, rows, background_);
  }

private:
  View view_;
  ShadeContext shade_;
  glm::vec3 background_;
  bool cull_back_;
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
