#include "raster/setup_cache.hpp"

#include <cstring>

#include "raster/renderer.hpp"

namespace zc {

SetupCache::SetupCache(std::shared_ptr<const Scene> held, const NodeRenderer& nr)
    : scene_(std::move(held)), view_(nr.view()), cull_back_(nr.cull_back()) {
  const Scene& scene = *scene_;
  Counters ignored;
  ForkSharedArray<ProjectedVertex> pv(scene.vertices.size());
  for (const Vertex& v : scene.vertices)
    pv.push_back(nr.project(v, ignored));
  const std::size_t n = scene.textured() ? 0 : scene.triangles.size();
  ForkSharedArray<Entry> entries(n);
  ForkSharedArray<ScreenTriangle> tris(n); // one a triangle at most, unless clipped
  TriangleBatch batch;
  for (std::uint32_t id = 0; id < n; ++id) { // none for a textured scene
    const Triangle& t = scene.triangles[id];
    const ProjectedVertex* const p[3] = {&pv[t.v[0]], &pv[t.v[1]], &pv[t.v[2]]};
    Counters c;
    batch.clear();
    const SetupInput in{{p[0], p[1], p[2]}, {nullptr, nullptr, nullptr}, id, t.material};
    setup_triangle(in, view_.width, view_.height, cull_back_, batch, c);
    Entry e;
    e.first = std::uint32_t(tris.size());
    e.count = std::uint8_t(batch.tris.size());
    e.culled = std::uint8_t(c.triangles_culled);
    e.clipped = std::uint8_t(c.triangles_clipped);
    int y0 = 0, y1 = -1;
    if (row_extent(p, view_.width, view_.height, y0, y1)) {
      e.y0 = y0;
      e.y1 = y1;
    }
    entries.push_back(e);
    for (const ScreenTriangle& st : batch.tris)
      tris.push_back(st);
  }
  pv_ = std::move(pv);
  entries_ = std::move(entries);
  tris_ = std::move(tris);
}

void SetupCache::map_in() const {
  if (mapped_in_.exchange(true)) return;
  pv_.map_in();
  entries_.map_in();
  tris_.map_in();
}

bool SetupCache::same_vertices(std::uint32_t id, const ProjectedVertex* const p[3]) const {
  if (id >= entries_.size()) return false; // none held for a textured scene
  const Triangle& t = scene_->triangles[id];
  for (int k = 0; k < 3; ++k)
    if (std::memcmp(p[k], &pv_[t.v[k]], sizeof(ProjectedVertex)) != 0) return false;
  return true;
}

bool SetupCache::setup(std::uint32_t id, std::uint32_t material, const ProjectedVertex* const p[3],
                       TriangleBatch& out, Counters& c) const {
  if (!same_vertices(id, p) || scene_->triangles[id].material != material) return false;
  const Entry& e = entries_[id];
  ++c.triangles_in;
  c.triangles_culled += e.culled;
  c.triangles_clipped += e.clipped;
  c.triangles_setup += e.count;
  out.tris.insert(out.tris.end(), tris_.data() + e.first, tris_.data() + e.first + e.count);
  return true;
}

SetupCache::Rows SetupCache::rows(std::uint32_t id, const ProjectedVertex* const p[3], int& y0,
                                  int& y1) const {
  if (!same_vertices(id, p)) return Rows::Unknown;
  const Entry& e = entries_[id];
  if (e.y0 > e.y1) return Rows::None;
  y0 = e.y0;
  y1 = e.y1;
  return Rows::Some;
}

namespace {
std::vector<std::unique_ptr<const SetupCache>>& caches() {
  static std::vector<std::unique_ptr<const SetupCache>> all;
  return all;
}
} // namespace

void add_setup_cache(std::unique_ptr<const SetupCache> cache) {
  caches().push_back(std::move(cache));
}

void drop_setup_caches(const std::function<bool(const Scene&)>& keep) {
  std::erase_if(caches(), [&keep](const auto& c) { return !keep(c->scene()); });
}

bool has_setup_cache(const Scene& scene) {
  for (const auto& c : caches())
    if (&c->scene() == &scene) return true;
  return false;
}

std::size_t setup_cache_count() {
  return caches().size();
}

const SetupCache* find_setup_cache(const Scene& scene, const View& view, bool cull_back) {
  for (const auto& c : caches())
    if (&c->scene() == &scene && c->cull_back() == cull_back && c->view().width == view.width &&
        c->view().height == view.height &&
        std::memcmp(&c->view().view_proj, &view.view_proj, sizeof view.view_proj) == 0) {
      c->map_in();
      return c.get();
    }
  return nullptr;
}

} // namespace zc
