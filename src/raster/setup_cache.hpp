#pragma once
// The set-up of a scene's triangles, worked out once by a process that then forks many
// simulations of that scene (`zcube reproduce`, sweeps): each simulation's nodes set up the same
// triangles from the same projected vertices (a screen triangle is a pure function of them,
// raster/setup.hpp), so they copy the result instead of computing it again. Blazek's 96 points
// set up 16.7 M triangles of four sphere scenes; each point read its triangles here instead.
//
// What a node gets is bit for bit what setup_triangle would give it, and so are its counters: a
// triangle is answered from the cache only when its id and material, the picture's size, the
// culling and the camera match and its three projected vertices are bit for bit the cached ones;
// anything else (another frame's camera, polygons projected anew with other bits, a textured
// scene) is set up as before. The cache only saves host time; no modelled cost changes.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "raster/setup.hpp"
#include "scene/scene.hpp"
#include "util/fork_shared_array.hpp"

namespace zc {

class NodeRenderer;

class SetupCache {
public:
  // Sets up every triangle of `scene` as `nr` would (nr renders that scene); holds none of a
  // textured scene.
  SetupCache(std::shared_ptr<const Scene> scene, const NodeRenderer& nr);

  const Scene& scene() const { return *scene_; }
  const View& view() const { return view_; }
  bool cull_back() const { return cull_back_; }
  // Maps the cache's pages in, once a process (a forked simulation about to read it).
  void map_in() const;

  // Appends triangle `id`'s screen triangles and counts its set-up into c, as setup_triangle
  // would, when the cache holds it for this material and these projected vertices; false (nothing
  // done) otherwise.
  bool setup(std::uint32_t id, std::uint32_t material, const ProjectedVertex* const p[3],
             TriangleBatch& out, Counters& c) const;
  // row_extent's answer for triangle `id` from these vertices, when the cache holds it.
  enum class Rows { Unknown, None, Some };
  Rows rows(std::uint32_t id, const ProjectedVertex* const p[3], int& y0, int& y1) const;

private:
  struct Entry {
    std::uint32_t first = 0;      // its screen triangles: tris_[first, first + count)
    std::uint8_t count = 0;       // screen triangles emitted (several when clipped)
    std::uint8_t culled = 0;      // triangles_culled it counted
    std::uint8_t clipped = 0;     // triangles_clipped it counted
    std::int32_t y0 = 0, y1 = -1; // row_extent's rows; y0 > y1: it touches none
  };
  bool same_vertices(std::uint32_t id, const ProjectedVertex* const p[3]) const;

  mutable std::atomic<bool> mapped_in_{false};
  std::shared_ptr<const Scene> scene_; // held: no other scene can take its address
  View view_;
  bool cull_back_;
  // Read by every forked simulation (util/fork_shared_array.hpp).
  ForkSharedArray<ProjectedVertex> pv_; // the scene's vertices projected
  ForkSharedArray<Entry> entries_;      // one per scene triangle
  ForkSharedArray<ScreenTriangle> tris_;
};

// The caches this process holds (set by the process that forks a batch; none elsewhere). A
// renderer of `scene` looks its cache up once, when it is made.
void add_setup_cache(std::unique_ptr<const SetupCache> cache);
// Drops the caches of the scenes `keep` rejects.
void drop_setup_caches(const std::function<bool(const Scene&)>& keep);
bool has_setup_cache(const Scene& scene);
std::size_t setup_cache_count();
const SetupCache* find_setup_cache(const Scene& scene, const View& view, bool cull_back);

} // namespace zc
