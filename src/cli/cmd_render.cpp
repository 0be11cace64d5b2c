// zcube render: the host renderer, real wall-clock (no simulation).
#include <filesystem>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/paths.hpp"
#include "raster/image_io.hpp"
#include "raster/renderer.hpp"
#include "repro/provenance.hpp"
#include "scene/load.hpp"
#include "util/image_size.hpp"
#include "util/output_file.hpp"
#include "util/stdout_result.hpp"

namespace zc::cli {

static int cmd_render(std::vector<std::string> args) {
  CLI::App app{"Render a scene on the host (real wall-clock; the reference image)", "zcube render"};
  std::string scene_path = default_scene_path(), image, depth, size, report;
  int threads = 1;
  app.add_option("--scene", scene_path, "JSON scene, Blazek scene file, OBJ or Bezier patches")
      ->capture_default_str();
  app.add_option("--image", image,
                 "output image (PNG; default: the scene's name in the working directory, e.g. "
                 "teapot.png)");
  app.add_option("--depth", depth, "output depth (EXR)");
  app.add_option("--size", size, "image size WxH (overrides the scene's)");
  app.add_option("--threads", threads, "host threads (the image is identical for any count)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  app.add_option("--report", report,
                 "write counters and wall time as JSON (- or /dev/stdout: to standard output, "
                 "the summary to standard error)");
  if (int rc = parse(app, args); rc >= 0) return rc;
  scene_path = data_file(scene_path);
  if (image.empty()) image = std::filesystem::path(scene_path).stem().string() + ".png";

  if (names_stdout(report)) reserve_stdout_for_result();
  check_output_paths({{"--image", image},
                      {"--depth", depth},
                      {"--report", names_stdout(report) ? std::string() : report}});
  check_image_path(image, "--image");
  check_image_path(depth, "--depth");
  LoadOptions lo;
  if (!size.empty()) {
    const ImageSize s = parse_image_size(size);
    lo.width = s.width;
    lo.height = s.height;
  }
  const Scene scene = load_scene(scene_path, lo);
  const RenderResult r = render_scene(scene, threads);
  write_png(r.image, image);
  if (!depth.empty()) write_depth_exr(r.image, depth);
  const std::string sha = image_sha256(r.image);
  if (!report.empty()) {
    nlohmann::json j;
    j["scene"] = {{"path", scene_path},
                  {"triangles", scene.triangles.size()},
                  {"vertices", scene.vertices.size()},
                  {"width", scene.width},
                  {"height", scene.height}};
    j["threads"] = threads;
    j["counters"] = r.counters;
    j["image"] = {{"path", image}, {"sha256", sha}};
    j["host"] = {{"wall_time_s", r.wall_time_s}};
    j["provenance"] = provenance();
    write_result_file(report, j.dump(2) + "\n");
  }
  std::cout << "image: " << image << "  (" << scene.width << "x" << scene.height << ", "
            << scene.triangles.size() << " triangles, " << r.counters.pixels_generated
            << " pixels generated, " << r.counters.pixels_final << " final, " << r.wall_time_s * 1e3
            << " ms on " << threads << " thread" << (threads > 1 ? "s" : "") << ")\n"
            << "sha256: " << sha << "\n";
  return 0;
}

ZC_COMMAND("render", "render a scene on the host (the reference image)", cmd_render);

} // namespace zc::cli
