#pragma once
// Mesa llvmpipe side of the benchmark: the scene's triangles drawn by desktop OpenGL (3.3 core)
// in a surfaceless EGL context (EGL_MESA_platform_surfaceless) into a frame buffer object with a
// depth test, in a child process so that LP_NUM_THREADS applies to a fresh Mesa context.
#include <cstdint>
#include <string>
#include <vector>

namespace zc::bench {

// What the GL side draws: world-space positions, per-vertex colours, the indexed triangles, and
// zcube's own view-projection matrix (column-major), so both renderers project the same geometry.
struct GlScene {
  std::vector<float> position; // x y z per vertex (world space)
  std::vector<float> color;    // r g b per vertex (Gouraud light times the material colour)
  std::vector<std::uint32_t> index;
  float view_proj[16] = {};
  bool cull_back = false; // GL_CULL_FACE with GL_BACK, counter-clockwise front faces
  int width = 0, height = 0;
};

struct GlResult {
  bool ok = false;
  std::string renderer; // GL_RENDERER (should name llvmpipe)
  double seconds = 0;   // median time of one frame: clear + draw + glFinish
  std::uint64_t fragments =
      0; // fragments rasterised in one frame (GL_SAMPLES_PASSED, no depth test)
  std::string error;
};

// cpu_time: frames timed in CPU time of the GL process (all its threads) instead of wall time.
GlResult gl_time_frame(const GlScene& scene, int lp_threads, double min_seconds,
                       bool cpu_time = false);

} // namespace zc::bench
