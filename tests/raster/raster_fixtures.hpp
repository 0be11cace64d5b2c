#pragma once
// Helpers for renderer tests: scenes and screen-space triangles built in code.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "raster/framebuffer.hpp"
#include "raster/setup.hpp"
#include "raster/zbuffer.hpp"
#include "scene/scene.hpp"

namespace zc::test {

// A projected vertex at screen position (sx, sy) in pixels, window depth z, with w = 1.
inline ProjectedVertex screen_vertex(double sx, double sy, double z, int w, int h,
                                     glm::vec3 light = glm::vec3(1)) {
  ProjectedVertex p{};
  p.clip[0] = float(2.0 * sx / w - 1.0);
  p.clip[1] = float(1.0 - 2.0 * sy / h);
  p.clip[2] = float(2.0 * z - 1.0);
  p.clip[3] = 1.0f;
  p.light[0] = light.x;
  p.light[1] = light.y;
  p.light[2] = light.z;
  return p;
}

// Every triangle of `tris` set up on a w x h screen (ids 0, 1, ...); its counters in `out`.
inline TriangleBatch setup_all(const std::vector<std::array<ProjectedVertex, 3>>& tris, int w,
                               int h, bool cull = false, Counters* out = nullptr) {
  TriangleBatch b;
  Counters c;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    SetupInput in{
        {&tris[i][0], &tris[i][1], &tris[i][2]}, {nullptr, nullptr, nullptr}, std::uint32_t(i), 0};
    setup_triangle(in, w, h, cull, b, c);
  }
  if (out) *out = c;
  return b;
}

// The triangle of test_renderer's HandCountedRightTriangle (pixel corners (0,0), (8,0), (0,8):
// rows 0-6, columns 0 to 6 - y) set up on a w x h screen.
inline TriangleBatch right_triangle(int w, int h, Counters* out = nullptr) {
  return setup_all({{screen_vertex(0, 0, .5, w, h), screen_vertex(8, 0, .5, w, h),
                     screen_vertex(0, 8, .5, w, h)}},
                   w, h, false, out);
}

// Per-pixel hit counts of a batch over the whole screen (coverage only, no depth test).
inline std::vector<int> coverage(const TriangleBatch& b, int w, int h) {
  std::vector<int> hits(std::size_t(w) * h, 0);
  for (const auto& t : b.tris)
    for_each_span(t, RowSet::all(h), w, [&](int y, int x0, int x1) {
      for (int x = x0; x <= x1; ++x)
        ++hits[std::size_t(y) * w + x];
    });
  return hits;
}

// Deterministic pseudo-random numbers for test scenes (splitmix64).
struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * (1.0 / 9007199254740992.0); }
};

// A unit sphere by recursive subdivision of an octahedron (closed, consistently wound CCW outside).
inline void add_sphere(Scene& s, glm::vec3 c, float r, int levels) {
  std::vector<glm::vec3> tris = {
      {1, 0, 0}, {0, 1, 0},  {0, 0, 1},  {0, 1, 0},  {-1, 0, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0},
      {0, 0, 1}, {0, -1, 0}, {1, 0, 0},  {0, 0, 1},  {0, 1, 0},  {1, 0, 0}, {0, 0, -1}, {-1, 0, 0},
      {0, 1, 0}, {0, 0, -1}, {0, -1, 0}, {-1, 0, 0}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  for (int l = 0; l < levels; ++l) {
    std::vector<glm::vec3> n;
    for (std::size_t i = 0; i < tris.size(); i += 3) {
      glm::vec3 a = tris[i], b = tris[i + 1], cc = tris[i + 2];
      glm::vec3 ab = glm::normalize(a + b), bc = glm::normalize(b + cc),
                ca = glm::normalize(cc + a);
      for (glm::vec3 v : {a, ab, ca, ab, b, bc, ca, bc, cc, ab, bc, ca})
        n.push_back(v);
    }
    tris.swap(n);
  }
  // Shared vertices (exact duplicates merged) so the mesh is closed.
  std::vector<glm::vec3> uniq;
  for (std::size_t i = 0; i < tris.size(); i += 3) {
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p = tris[i + k];
      std::uint32_t idx = 0;
      for (; idx < uniq.size(); ++idx)
        if (uniq[idx] == p) break;
      if (idx == uniq.size()) uniq.push_back(p);
      t.v[k] = std::uint32_t(s.vertices.size()) + idx;
    }
    s.triangles.push_back(t);
  }
  for (auto p : uniq)
    s.vertices.push_back({c + r * p, p});
}

inline Scene base_scene(int w, int h) {
  Scene s;
  s.width = w;
  s.height = h;
  s.camera.eye = {0, 0, 5};
  s.camera.target = {0, 0, 0};
  s.camera.fovy_deg = 45;
  s.camera.znear = 0.5;
  s.camera.zfar = 50;
  s.lights.push_back({{-1, -1, -1}, {0.9f, 0.9f, 0.9f}});
  return s;
}

} // namespace zc::test
