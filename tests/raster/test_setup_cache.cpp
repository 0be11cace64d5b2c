// The set-up cache (raster/setup_cache.hpp) against set-up itself: the same screen triangles, bit
// for bit, the same counters, and the same rows as row_extent, for triangles inside the view, cut
// by its planes and outside it; and nothing from it when the vertices, the material, the camera or
// the picture differ.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>

#include "raster/renderer.hpp"
#include "raster/setup_cache.hpp"
#include "raster/zbuffer.hpp"
#include "raster_fixtures.hpp"

using namespace zc;

namespace {

// Random triangles around the camera: most inside the view, some across the near plane or the
// guard band, some behind the eye, some degenerate; two materials.
std::shared_ptr<const Scene> random_scene(int w, int h) {
  Scene s = test::base_scene(w, h);
  s.materials.push_back(Material{"red", {0.9f, 0.1f, 0.1f}, -1});
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> near_box(-1.5f, 1.5f), wide(-12.f, 12.f);
  for (int t = 0; t < 3000; ++t) {
    const bool wide_one = t % 5 == 0;
    for (int k = 0; k < 3; ++k) {
      glm::vec3 p = wide_one ? glm::vec3(wide(rng), wide(rng), wide(rng))
                             : glm::vec3(near_box(rng), near_box(rng), near_box(rng));
      if (t % 97 == 0 && k == 2) p = s.vertices.back().position; // a degenerate one
      s.vertices.push_back({p, glm::normalize(glm::vec3(0.3f, 0.2f, 1.f))});
    }
    const auto v = std::uint32_t(3 * t);
    s.triangles.push_back(Triangle{{v, v + 1, v + 2}, std::uint32_t(t % 2)});
  }
  return std::make_shared<const Scene>(std::move(s));
}

void corners(const std::vector<ProjectedVertex>& pv, const Triangle& t,
             const ProjectedVertex* (&p)[3]) {
  for (int k = 0; k < 3; ++k)
    p[k] = &pv[t.v[k]];
}

} // namespace

// Outside the anonymous namespace: the test classes TEST_F derives from it have external linkage.
struct SetupCacheTest : ::testing::Test {
  void TearDown() override {
    drop_setup_caches([](const Scene&) { return false; });
  }
};

TEST_F(SetupCacheTest, GivesWhatSetUpGivesBitForBit) {
  for (const bool cull : {false, true}) {
    auto scene = random_scene(97, 61);
    if (cull) {
      Scene s = *scene;
      s.cull = CullMode::Back;
      scene = std::make_shared<const Scene>(std::move(s));
    }
    const NodeRenderer plain(*scene); // made before the cache: sets up by itself
    const SetupCache cache(scene, plain);
    std::vector<ProjectedVertex> pv;
    Counters ignored;
    for (const Vertex& v : scene->vertices)
      pv.push_back(plain.project(v, ignored));
    int clipped = 0, culled = 0, emitted = 0, no_rows = 0;
    for (std::uint32_t id = 0; id < scene->triangles.size(); ++id) {
      const Triangle& t = scene->triangles[id];
      const ProjectedVertex* p[3];
      corners(pv, t, p);
      TriangleBatch direct, cached;
      Counters cd, cc;
      plain.setup_projected(id, t, p, nullptr, direct, cd);
      ASSERT_TRUE(cache.setup(id, t.material, p, cached, cc)) << id;
      ASSERT_EQ(direct.tris.size(), cached.tris.size()) << id;
      if (!direct.tris.empty()) {
        EXPECT_EQ(0, std::memcmp(direct.tris.data(), cached.tris.data(),
                                 direct.tris.size() * sizeof(ScreenTriangle)))
            << id;
      }
      EXPECT_EQ(cd.triangles_in, cc.triangles_in);
      EXPECT_EQ(cd.triangles_culled, cc.triangles_culled) << id;
      EXPECT_EQ(cd.triangles_clipped, cc.triangles_clipped) << id;
      EXPECT_EQ(cd.triangles_setup, cc.triangles_setup) << id;
      int y0 = -7, y1 = -7, r0 = -7, r1 = -7;
      const bool any = row_extent(p, 97, 61, y0, y1);
      const SetupCache::Rows rows = cache.rows(id, p, r0, r1);
      ASSERT_NE(rows, SetupCache::Rows::Unknown) << id;
      EXPECT_EQ(any, rows == SetupCache::Rows::Some) << id;
      if (any) {
        EXPECT_TRUE(y0 == r0 && y1 == r1) << id;
      }
      clipped += int(cd.triangles_clipped);
      culled += int(cd.triangles_culled);
      emitted += int(cd.triangles_setup);
      no_rows += !any;
    }
    // The scene exercises every path of set-up.
    EXPECT_GT(clipped, 50);
    EXPECT_GT(culled, 50);
    EXPECT_GT(emitted, 1000);
    EXPECT_GT(no_rows, 50);
  }
}

TEST_F(SetupCacheTest, AnswersNothingForOtherVerticesOrMaterial) {
  const auto scene = random_scene(64, 48);
  const NodeRenderer nr(*scene);
  const SetupCache cache(scene, nr);
  Counters ignored;
  const Triangle& t = scene->triangles[1];
  ProjectedVertex v[3] = {nr.project(scene->vertices[t.v[0]], ignored),
                          nr.project(scene->vertices[t.v[1]], ignored),
                          nr.project(scene->vertices[t.v[2]], ignored)};
  const ProjectedVertex* const p[3] = {&v[0], &v[1], &v[2]};
  TriangleBatch out;
  Counters c;
  EXPECT_TRUE(cache.setup(1, t.material, p, out, c));
  EXPECT_FALSE(cache.setup(1, t.material + 1, p, out, c)); // another material
  EXPECT_FALSE(cache.setup(2, t.material, p, out, c));     // another triangle's id
  EXPECT_FALSE(cache.setup(std::uint32_t(scene->triangles.size()), t.material, p, out, c));
  v[2].clip[0] = std::nextafter(v[2].clip[0], 1e9f); // one bit off
  EXPECT_FALSE(cache.setup(1, t.material, p, out, c));
  int y0 = 0, y1 = 0;
  EXPECT_EQ(cache.rows(1, p, y0, y1), SetupCache::Rows::Unknown);
  EXPECT_EQ(c.triangles_in, 1u); // only the first call counted
}

TEST_F(SetupCacheTest, RenderersFindItOnlyForTheSameSceneViewAndCulling) {
  const auto scene = random_scene(64, 48);
  add_setup_cache(std::make_unique<const SetupCache>(scene, NodeRenderer(*scene)));
  const NodeRenderer same(*scene);
  EXPECT_NE(find_setup_cache(*scene, same.view(), same.cull_back()), nullptr);
  EXPECT_EQ(find_setup_cache(*scene, same.view(), !same.cull_back()), nullptr);
  Camera other = scene->camera;
  other.eye.x += 0.25;
  const NodeRenderer moved(*scene, other);
  EXPECT_EQ(find_setup_cache(*scene, moved.view(), moved.cull_back()), nullptr);
  const Scene copy = *scene; // the same triangles in another scene: not this cache's
  EXPECT_EQ(find_setup_cache(copy, same.view(), same.cull_back()), nullptr);
  EXPECT_TRUE(has_setup_cache(*scene));
  drop_setup_caches([](const Scene&) { return false; });
  EXPECT_FALSE(has_setup_cache(*scene));
}

TEST_F(SetupCacheTest, RenderingWithTheCacheDrawsTheSamePicture) {
  const auto scene = random_scene(80, 60);
  const auto before = render_scene(*scene, 1);
  add_setup_cache(std::make_unique<const SetupCache>(scene, NodeRenderer(*scene)));
  const NodeRenderer nr(*scene);
  ASSERT_NE(find_setup_cache(*scene, nr.view(), nr.cull_back()), nullptr);
  // A node's path: its renderer sets up from the cache, then draws.
  std::vector<ProjectedVertex> pv;
  Counters c;
  for (const Vertex& v : scene->vertices)
    pv.push_back(nr.project(v, c));
  Framebuffer fb = nr.make_framebuffer(RowSet::all(60));
  TriangleBatch batch;
  for (std::uint32_t id = 0; id < scene->triangles.size(); ++id)
    nr.setup(id, scene->triangles[id], pv.data(), nullptr, batch, c);
  draw_batch(batch, nr.shade(), fb, c);
  EXPECT_EQ(fb.ids(), before.image.ids());
  EXPECT_EQ(fb.depth(), before.image.depth());
  EXPECT_EQ(fb.rgb(), before.image.rgb());
  EXPECT_EQ(c.triangles_setup, before.counters.triangles_setup);
  EXPECT_EQ(c.triangles_clipped, before.counters.triangles_clipped);
}
