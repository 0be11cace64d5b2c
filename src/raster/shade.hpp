#pragma once
// Fragment stage: depth and colour of one pixel of one screen triangle. Gouraud shading (Charles
// et al. §2: vertex colours interpolated across the triangle) times the material's diffuse colour,
// times a texel when, and only when, the material has a texture.
#include <cmath>
#include <cstdint>
#include <vector>

#include "raster/setup.hpp"
#include "scene/scene.hpp"
#include "util/counters.hpp"

namespace zc {

struct Fragment {
  float z;
  std::uint8_t rgb[3];
};

struct ShadeContext {
  const std::vector<Material>* materials = nullptr;
  const std::vector<Texture>* textures = nullptr; // null for an untextured scene
  TextureFilter filter = TextureFilter::Bilinear;

  static ShadeContext of(const Scene& s) {
    return {&s.materials, s.textured() ? &s.textures : nullptr, s.filter};
  }
};

inline std::uint8_t unit_to_byte(float c) {
  const float v = c <= 0.f ? 0.f : (c >= 1.f ? 1.f : c);
  return static_cast<std::uint8_t>(v * 255.f + 0.5f);
}

// Samples texture `t` at (u, v) with repeat wrapping; v = 0 is the bottom row (OBJ convention).
glm::vec3 sample_texture(const Texture& t, float u, float v, TextureFilter f, Counters& c);

// Per-row precomputation of a triangle's planes, so a span costs one multiply-add per attribute.
struct RowShader {
  const ScreenTriangle* t;
  const TexPlanes* tp; // null when untextured
  glm::vec3 kd;
  const Texture* texture;
  TextureFilter filter;
  int y;
  double z0, r0, g0, b0, uw0 = 0, vw0 = 0, w10 = 0;

  RowShader(const ScreenTriangle& tri, const TriangleBatch& batch, const ShadeContext& ctx, int row)
      : t(&tri), tp(tri.tex >= 0 ? &batch.tex[tri.tex] : nullptr),
        kd((*ctx.materials)[tri.material].kd), texture(nullptr), filter(ctx.filter), y(row) {
    z0 = tri.z.row(y);
    r0 = tri.r.row(y);
    g0 = tri.g.row(y);
    b0 = tri.b.row(y);
    if (tp) {
      const int ti = (*ctx.materials)[tri.material].texture;
      if (ctx.textures && ti >= 0) texture = &(*ctx.textures)[ti];
      uw0 = tp->uw.row(y);
      vw0 = tp->vw.row(y);
      w10 = tp->w1.row(y);
    }
  }

  float depth(int x) const { return static_cast<float>(z0 + t->z.ax * x); }

  void color(int x, std::uint8_t out[3], Counters& c) const {
    glm::vec3 col(float(r0 + t->r.ax * x), float(g0 + t->g.ax * x), float(b0 + t->b.ax * x));
    col *= kd;
    if (texture) {
      const double w1 = w10 + tp->w1.ax * x;
      const float u = float((uw0 + tp->uw.ax * x) / w1);
      const float v = float((vw0 + tp->vw.ax * x) / w1);
      col *= sample_texture(*texture, u, v, filter, c);
    }
    out[0] = unit_to_byte(col.x);
    out[1] = unit_to_byte(col.y);
    out[2] = unit_to_byte(col.z);
  }
};

} // namespace zc
