#include "algo/sequential.hpp"

#include "algo/records.hpp"
#include "geometry/camera_path.hpp"
#include "raster/renderer.hpp"
#include "raster/zbuffer.hpp"

namespace zc {

namespace {

void sequential_node(NodeContext& ctx) {
  if (ctx.rank() != 0) return;
  const Scene& base = ctx.scene();
  const int frames = ctx.options().frames;
  // The scene it renders in Charles et al.'s records (§4, records.hpp): vertices of six reals,
  // triangles of three vertex numbers.
  ctx.alloc(double(base.vertices.size() * records::charles::kVertex +
                   base.triangles.size() * records::charles::kTriangle),
            "scene");
  for (int f = 0; f < frames; ++f) {
    const NodeRenderer nr(base, camera_at_frame(base.camera, f, frames), ctx.scene_facts().bounds);
    // The frame buffer (depth and colour) and the projected vertices, as the paper's records.
    const double fb_bytes =
        double(base.width) * base.height * double(records::charles::kZbufferLocation);
    const double pv_bytes =
        double(base.vertices.size()) * double(records::charles::kProjectedVertex);
    ctx.alloc(fb_bytes + pv_bytes, "frame buffer and projected vertices");
    std::vector<ProjectedVertex> pv(base.vertices.size());
    {
      auto ph = ctx.phase("project");
      Counters c;
      for (std::size_t i = 0; i < pv.size(); ++i)
        pv[i] = nr.project(base.vertices[i], c);
      ctx.charge(c);
    }
    Framebuffer fb = nr.make_framebuffer(RowSet::all(base.height));
    {
      auto ph = ctx.phase("zbuffer");
      Counters c;
      c.pixels_cleared = std::uint64_t(base.width) * base.height;
      TriangleBatch batch;
      for (std::size_t i = 0; i < base.triangles.size(); ++i) {
        batch.clear();
        nr.setup(std::uint32_t(i), base.triangles[i], pv.data(), base.uvs_if_textured(), batch, c);
        draw_batch(batch, nr.shade(), fb, c);
      }
      c.pixels_final = fb.covered();
      ctx.charge(c);
    }
    ctx.release(fb_bytes + pv_bytes);
    ctx.deliver_image(f, std::move(fb));
  }
}

} // namespace

Algorithm sequential_algorithm() {
  Algorithm a;
  a.name = "sequential";
  a.summary = "one node renders everything (the reference for speed-ups)";
  a.node = sequential_node;
  a.renders_frames = true;
  return a;
}

} // namespace zc
