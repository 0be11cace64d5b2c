// Reference renderer: fill rule, clipping, depth tie-break, thread independence, counters.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "raster/image_io.hpp"
#include "raster/renderer.hpp"
#include "raster/zbuffer.hpp"
#include "raster_fixtures.hpp"

using namespace zc;
using namespace zc::test;

TEST(Raster, HandCountedRightTriangle) {
  // Vertices on pixel corners (0,0), (8,0), (0,8) of an 8x8 screen: the centres (x+.5, y+.5)
  // strictly inside satisfy x + y <= 6 (28 pixels); the 8 centres exactly on the hypotenuse
  // (x + y = 7) lie on a right edge and are excluded by the top-left rule.
  const int w = 8, h = 8;
  Counters c;
  auto b = right_triangle(w, h, &c);
  ASSERT_EQ(b.tris.size(), 1u);
  EXPECT_EQ(c.triangles_in, 1u);
  EXPECT_EQ(c.triangles_setup, 1u);
  EXPECT_EQ(c.triangles_clipped, 0u);
  auto hits = coverage(b, w, h);
  int n = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int expect = (x + y <= 6) ? 1 : 0;
      EXPECT_EQ(hits[y * w + x], expect) << x << "," << y;
      n += hits[y * w + x];
    }
  EXPECT_EQ(n, 28);

  Framebuffer fb(w, RowSet::all(h), glm::vec3(0));
  Counters dc;
  ShadeContext ctx;
  std::vector<Material> mats{Material{}};
  ctx.materials = &mats;
  draw_batch(b, ctx, fb, dc);
  EXPECT_EQ(dc.spans, 7u); // rows 0..6
  EXPECT_EQ(dc.pixels_generated, 28u);
  EXPECT_EQ(dc.pixels_written, 28u);
  EXPECT_EQ(fb.covered(), 28u);
}

TEST(Raster, SharedEdgeQuadCoversEachPixelOnce) {
  const int w = 16, h = 16;
  // A quad with a diagonal through pixel centres, in both triangle orders and windings.
  auto v = [&](double x, double y) { return screen_vertex(x, y, .5, w, h); };
  auto b = setup_all({{v(2, 2), v(14, 2), v(2, 14)}, {v(14, 2), v(14, 14), v(2, 14)}}, w, h);
  auto hits = coverage(b, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      EXPECT_EQ(hits[y * w + x], (x >= 2 && x < 14 && y >= 2 && y < 14) ? 1 : 0) << x << "," << y;
}

TEST(Raster, JitteredGridIsWatertight) {
  // A regular grid of 40x40 cells with jittered interior vertices at sub-pixel positions: every
  // pixel centre inside the (axis-aligned) outline is hit exactly once.
  const int w = 97, h = 83, n = 40;
  Rng rng{42};
  std::vector<std::vector<glm::dvec2>> g(n + 1, std::vector<glm::dvec2>(n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = 3.0 + i * (w - 6.0) / n, y = 3.0 + j * (h - 6.0) / n;
      if (i > 0 && i < n && j > 0 && j < n) {
        x += (rng.uniform() - .5) * 1.4;
        y += (rng.uniform() - .5) * 1.4;
      }
      g[j][i] = {x, y};
    }
  std::vector<std::array<ProjectedVertex, 3>> tris;
  auto v = [&](int i, int j) { return screen_vertex(g[j][i].x, g[j][i].y, .5, w, h); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      tris.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      tris.push_back({v(i, j), v(i, j + 1), v(i + 1, j + 1)}); // opposite winding on purpose
    }
  auto b = setup_all(tris, w, h);
  auto hits = coverage(b, w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      ASSERT_EQ(hits[y * w + x], (x >= 3 && x < w - 3 && y >= 3 && y < h - 3) ? 1 : 0)
          << x << "," << y;
}

TEST(Raster, ClosedSphereHasNoCracks) {
  Scene s = base_scene(128, 96);
  add_sphere(s, {0.2f, -0.1f, 0}, 1.3f, 4);
  for (const auto& t : s.triangles) { // the fixture is wound outwards
    glm::vec3 a = s.vertices[t.v[0]].position, b = s.vertices[t.v[1]].position,
              c = s.vertices[t.v[2]].position;
    ASSERT_GT(glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.f - glm::vec3(0.2f, -0.1f, 0)), 0);
  }
  NodeRenderer nr(s);
  for (bool cull : {false, true}) {
    TriangleBatch b;
    Counters c;
    std::vector<ProjectedVertex> pv;
    for (const auto& v : s.vertices)
      pv.push_back(nr.project(v, c));
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
      const auto& t = s.triangles[i];
      SetupInput in{{&pv[t.v[0]], &pv[t.v[1]], &pv[t.v[2]]},
                    {nullptr, nullptr, nullptr},
                    std::uint32_t(i),
                    0};
      setup_triangle(in, s.width, s.height, cull, b, c);
    }
    auto hits = coverage(b, s.width, s.height);
    int inside = 0;
    for (int hcount : hits) {
      // Closed convex surface: 2 layers (front and back) without culling, 1 with it.
      ASSERT_TRUE(hcount == 0 || hcount == (cull ? 1 : 2)) << hcount;
      inside += hcount > 0;
    }
    EXPECT_GT(inside, 2000);
  }
}

TEST(Raster, NearPlaneCrossingIsClippedNotDropped) {
  // A floor quad running from behind the eye to far away: it must be clipped at the near plane
  // and still cover the lower part of the screen up to the horizon.
  Scene s = base_scene(64, 64);
  s.camera.eye = {0, 1, 0};
  s.camera.target = {0, 1, -1};
  s.camera.znear = 0.1;
  s.camera.zfar = 1000;
  s.vertices = {{{-100, 0, 50}, {0, 1, 0}},
                {{100, 0, 50}, {0, 1, 0}},
                {{100, 0, -500}, {0, 1, 0}},
                {{-100, 0, -500}, {0, 1, 0}}};
  s.triangles = {Triangle{{0, 1, 2}, 0}, Triangle{{0, 2, 3}, 0}};
  auto r = render_scene(s, 1);
  EXPECT_EQ(r.counters.triangles_clipped, 2u);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const bool covered = r.image.ids()[std::size_t(y) * 64 + x] != kNoTriangle;
      if (y >= 40) {
        EXPECT_TRUE(covered) << x << "," << y; // well below the horizon
      }
      if (y < 30) {
        EXPECT_FALSE(covered) << x << "," << y; // above it
      }
    }
}

TEST(Raster, HugeCoordinatesAreSafe) {
  // Vertices at 1e30 (and behind the eye): no overflow, no crash, and a triangle that contains
  // the whole view covers every pixel exactly once.
  Scene s = base_scene(48, 32);
  s.camera.zfar = 1e3;
  s.vertices = {{{-1e30f, -1e30f, -2}, {0, 0, 1}}, {{1e30f, -1e30f, -2}, {0, 0, 1}},
                {{0, 1e30f, -2}, {0, 0, 1}},       {{1e30f, 1e30f, 1e30f}, {0, 0, 1}},
                {{-1e30f, 5, 1e30f}, {0, 0, 1}},   {{3, -1e30f, -1e30f}, {0, 0, 1}}};
  s.triangles = {Triangle{{0, 1, 2}, 0}, Triangle{{3, 4, 5}, 0}};
  auto r = render_scene(s, 1);
  EXPECT_EQ(r.counters.pixels_final, 48u * 32u);
  auto r2 = render_scene(s, 3);
  EXPECT_EQ(image_sha256(r.image), image_sha256(r2.image));
}

TEST(Raster, DegenerateTrianglesAreSkipped) {
  const int w = 16, h = 16;
  auto v = [&](double x, double y) { return screen_vertex(x, y, .5, w, h); };
  Counters c;
  auto b = setup_all({{v(1, 1), v(5, 5), v(9, 9)}, {v(3, 3), v(3, 3), v(3, 3)}}, w, h, false, &c);
  EXPECT_TRUE(b.tris.empty());
  EXPECT_EQ(c.triangles_culled, 2u);
}

TEST(Raster, ZFightingTieBreakIsOrderIndependent) {
  // Two coplanar, overlapping triangles with different colours: whatever the submission order,
  // every pixel of the overlap shows the lower id.
  const int w = 32, h = 32;
  auto red = [&](double x, double y) { return screen_vertex(x, y, .4, w, h, {1, 0, 0}); };
  auto blue = [&](double x, double y) { return screen_vertex(x, y, .4, w, h, {0, 0, 1}); };
  std::vector<Material> mats{Material{"", glm::vec3(1), -1}};
  ShadeContext ctx;
  ctx.materials = &mats;
  std::string hashes[2];
  for (int order = 0; order < 2; ++order) {
    std::array<ProjectedVertex, 3> a{red(1, 1), red(30, 2), red(3, 30)};
    std::array<ProjectedVertex, 3> bb{blue(2, 3), blue(31, 31), blue(28, 1)};
    TriangleBatch batch;
    Counters c;
    const std::array<ProjectedVertex, 3>* tri[2] = {&a, &bb};
    for (int k = 0; k < 2; ++k) {
      const int i = order == 0 ? k : 1 - k;
      SetupInput in{{&(*tri[i])[0], &(*tri[i])[1], &(*tri[i])[2]},
                    {nullptr, nullptr, nullptr},
                    std::uint32_t(i),
                    0};
      setup_triangle(in, w, h, false, batch, c);
    }
    Framebuffer fb(w, RowSet::all(h), glm::vec3(0));
    draw_batch(batch, ctx, fb, c);
    hashes[order] = image_sha256(fb);
    int overlap = 0;
    auto cov = coverage(batch, w, h);
    for (std::size_t p = 0; p < cov.size(); ++p)
      if (cov[p] == 2) {
        ++overlap;
        EXPECT_EQ(fb.ids()[p], 0u);
        EXPECT_EQ(fb.rgb()[3 * p], 255);
      }
    EXPECT_GT(overlap, 100);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

namespace {

// Twelve recursion-3 spheres at seeded random places and sizes.
Scene spheres(int w, int h, std::uint64_t seed = 11) {
  Scene s = base_scene(w, h);
  Rng rng{seed};
  for (int k = 0; k < 12; ++k)
    add_sphere(s,
               {float(rng.uniform() * 4 - 2), float(rng.uniform() * 3 - 1.5),
                float(rng.uniform() * 2 - 1)},
               float(0.3 + rng.uniform() * 0.6), 3);
  return s;
}

// Every triangle of `s` projected and set up in scene order, counted into `c`.
TriangleBatch set_up_all(const NodeRenderer& nr, const Scene& s, Counters& c) {
  std::vector<ProjectedVertex> pv;
  for (const auto& v : s.vertices)
    pv.push_back(nr.project(v, c));
  TriangleBatch b;
  for (std::size_t i = 0; i < s.triangles.size(); ++i)
    nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, b, c);
  return b;
}

} // namespace

TEST(Raster, ImageAndCountersIndependentOfThreadCount) {
  const Scene s = spheres(160, 120, 7);
  const auto ref = render_scene(s, 1);
  const std::string h = image_sha256(ref.image);
  for (int t : {2, 3, 4, 7}) {
    const auto r = render_scene(s, t);
    EXPECT_EQ(image_sha256(r.image), h) << t << " threads";
    EXPECT_EQ(r.counters, ref.counters) << t << " threads";
  }
}

TEST(Raster, BandsAndChunksDrawWhatOnePassDraws) {
  // The renderer draws in row bands sized to the cache and in chunks of triangles (small ones on
  // a small frame buffer): the same pixels as every triangle drawn over the whole buffer in scene
  // order, frame after frame into a reused buffer.
  for (auto [w, h] : {std::pair{600, 300}, std::pair{1400, 400}}) {
    const Scene s = spheres(w, h);
    const NodeRenderer nr(s);
    Counters c;
    const TriangleBatch b = set_up_all(nr, s, c);
    ASSERT_GT(b.tris.size(), 4096u); // several chunks
    Framebuffer one_pass = nr.make_framebuffer(RowSet::all(h));
    draw_batch(b, nr.shade(), one_pass, c);
    Framebuffer fb;
    for (int frame = 0; frame < 2; ++frame) {
      const Counters r = render_scene_into(s, 1, fb);
      EXPECT_EQ(fb.rgb(), one_pass.rgb()) << w << "x" << h << " frame " << frame;
      EXPECT_EQ(fb.depth(), one_pass.depth()) << w << "x" << h;
      EXPECT_EQ(fb.ids(), one_pass.ids()) << w << "x" << h;
      EXPECT_EQ(r.edge_walks, c.edge_walks);
      EXPECT_EQ(r.spans, c.spans);
      EXPECT_EQ(r.pixels_generated, c.pixels_generated);
      EXPECT_EQ(r.pixels_written, c.pixels_written);
      EXPECT_EQ(r.pixels_final, one_pass.covered());
    }
  }
}

TEST(Raster, SpansDrawnOneByOneDrawWhatTheTrianglesDraw) {
  // draw_span (Kurc et al.'s ZBUF-EXC draws the spans of its lists) z-buffers the same pixels as
  // draw_batch, with its counts less the spans found and the edges walked.
  const Scene s = spheres(300, 200);
  const NodeRenderer nr(s);
  Counters c;
  const TriangleBatch b = set_up_all(nr, s, c);
  Framebuffer whole = nr.make_framebuffer(RowSet::all(200)), spans = whole;
  Counters cw, cs;
  draw_batch(b, nr.shade(), whole, cw);
  for (const auto& t : b.tris)
    for_each_span(t, spans.rows(), spans.width(), [&](int y, int x0, int x1) {
      draw_span(t, b, nr.shade(), y, x0, x1, spans, cs);
    });
  EXPECT_EQ(spans.rgb(), whole.rgb());
  EXPECT_EQ(spans.depth(), whole.depth());
  EXPECT_EQ(spans.ids(), whole.ids());
  EXPECT_EQ(cs.span_starts, cw.spans);
  EXPECT_EQ(cs.spans + cs.edge_walks, 0u);
  EXPECT_EQ(cs.pixels_generated, cw.pixels_generated);
  EXPECT_EQ(cs.pixels_tested, cw.pixels_tested);
  EXPECT_EQ(cs.pixels_written, cw.pixels_written);
  EXPECT_GT(cs.pixels_written, 1000u);
}

TEST(Raster, ConcurrentRendersShareNoThreads) {
  // Two host threads rendering at once: one uses the renderer's thread pool, the other threads of
  // its own; both images are the sequential one.
  const Scene s = spheres(200, 150);
  const std::string h = image_sha256(render_scene(s, 1).image);
  std::string a, b;
  std::thread other([&] { b = image_sha256(render_scene(s, 3).image); });
  a = image_sha256(render_scene(s, 2).image);
  other.join();
  EXPECT_EQ(a, h);
  EXPECT_EQ(b, h);
}

TEST(Raster, ForkedChildRendersOnThreadsOfItsOwn) {
  // A process forked after the renderer's thread pool started has none of its threads: its
  // renders must not wait for them.
  const Scene s = spheres(120, 90);
  const std::string h = image_sha256(render_scene(s, 2).image);
  const pid_t pid = fork();
  if (pid == 0) _exit(image_sha256(render_scene(s, 2).image) == h ? 0 : 1);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST(Raster, RowSubsetsReproduceTheFullImage) {
  // The property every image-space decomposition relies on: bands and interleaved rows rendered
  // separately and pasted give the full image, bit for bit.
  Scene s = base_scene(90, 70);
  add_sphere(s, {0, 0, 0}, 1.4f, 3);
  add_sphere(s, {0.8f, 0.5f, 0.6f}, 0.7f, 3);
  const auto ref = render_scene(s, 1);
  NodeRenderer nr(s);
  Counters c;
  std::vector<ProjectedVertex> pv;
  for (const auto& v : s.vertices)
    pv.push_back(nr.project(v, c));
  TriangleBatch b;
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    nr.setup(std::uint32_t(i), s.triangles[i], pv.data(), nullptr, b, c);
  }
  for (RowSet rs : {RowSet::band(0, 23), RowSet::band(23, 70), RowSet::interleaved(1, 3, 70),
                    RowSet::interleaved(0, 3, 70), RowSet::interleaved(2, 3, 70)}) {
    Framebuffer part = nr.make_framebuffer(rs);
    draw_batch(b, nr.shade(), part, c);
    Framebuffer full = nr.make_framebuffer(RowSet::all(70));
    full.paste(part);
    for (int y = rs.begin; y < rs.end; y += rs.stride)
      for (int x = 0; x < 90; ++x) {
        const std::size_t i = full.index(x, y);
        ASSERT_EQ(full.ids()[i], ref.image.ids()[i]);
        ASSERT_EQ(full.rgb()[3 * i], ref.image.rgb()[3 * i]);
      }
  }
}

TEST(Raster, EmptySceneRendersBackground) {
  Scene s = base_scene(20, 10);
  s.background = {0, 0, 1};
  auto r = render_scene(s, 2);
  EXPECT_EQ(r.counters.pixels_final, 0u);
  EXPECT_EQ(r.image.rgb()[2], 255);
}
