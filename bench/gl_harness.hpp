#pragma once
// Mesa llvmpipe side of the benchmark: the same projected triangles drawn by OpenGL ES 3 in a
// surfaceless EGL context into an off-screen frame buffer with a depth test.
#include <cstdint>
#include <string>
#include <vector>

#include "raster/view.hpp"

namespace zc::bench {

struct GlResult {
  bool ok = false;
  std::string renderer; // GL_RENDERER string (should name llvmpipe)
  double seconds = 0;   // median time of one frame (glFinish included)
  std::string error;
};

// Runs in a child process so that LP_NUM_THREADS applies to a fresh Mesa context.
GlResult gl_time_frame(const std::vector<ProjectedVertex>& pv,
                       const std::vector<std::uint32_t>& idx, int width, int height, int lp_threads,
                       double min_seconds);

} // namespace zc::bench
