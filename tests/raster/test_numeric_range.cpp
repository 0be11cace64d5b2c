// The coordinate range the renderer handles exactly (scenes/README.md 'Numeric range'):
// inside it a scene and its camera scaled by a power of two render the same bits, colour and
// depth; just outside it the scene is refused on loading, naming the file and the field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "raster/image_io.hpp"
#include "raster/renderer.hpp"
#include "scene/load.hpp"
#include "util/error.hpp"

using namespace zc;

namespace {

std::string write_scene(const std::string& name, const std::string& json) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("zcube-range-" + std::to_string(::getpid()) + "-" + name + ".json");
  std::ofstream(path) << json;
  return path.string();
}

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// Two spheres and a cube, seen off-axis, every coordinate multiplied by s.
std::string scaled_scene(double s, double fov = 40) {
  auto v = [&](double x, double y, double z) {
    return "[" + num(x * s) + "," + num(y * s) + "," + num(z * s) + "]";
  };
  return R"({"image":{"width":40,"height":30},"camera":{"eye":)" + v(1, 2, 5) + R"(,"target":)" +
         v(0, 0, 0) + R"(,"up":[0,1,0],"fov":)" + num(fov) +
         R"(},"objects":[{"type":"sphere","transform":{"translate":)" + v(0.3, 0.1, 0) +
         R"(,"scale":)" + num(s) + R"(}},{"type":"cube","transform":{"translate":)" +
         v(-1, -0.5, -1) + R"(,"scale":)" + num(0.5 * s) + R"(}}]})";
}

struct Picture {
  std::string rgb, depth;
  std::uint64_t pixels = 0;
};

Picture render(const std::string& name, const std::string& json) {
  const std::string path = write_scene(name, json);
  const Scene s = load_scene(path);
  std::filesystem::remove(path);
  auto r = render_scene(s, 1);
  Picture p;
  p.rgb = image_sha256(r.image);
  const auto& d = r.image.depth();
  p.depth.assign(reinterpret_cast<const char*>(d.data()), d.size() * sizeof(float));
  p.pixels = r.counters.pixels_final;
  return p;
}

// The InputError message loading `json` gives ("" when it loads).
std::string refusal(const std::string& name, const std::string& json) {
  const std::string path = write_scene(name, json);
  std::string msg;
  try {
    load_scene(path);
  } catch (const InputError& e) {
    msg = e.what();
  }
  std::filesystem::remove(path);
  return msg;
}

} // namespace

TEST(Range, PowerOfTwoScalesRenderTheSameBitsUpToTheEdges) {
  const Picture unit = render("unit", scaled_scene(1));
  ASSERT_GT(unit.pixels, 200u);
  // 2^61: the farthest coordinate (eye z = 5 s) stays below 2^64; 2^-60 keeps every extent above
  // 2^-64.
  for (int k : {-60, -30, -20, 20, 40, 61}) {
    const Picture p = render(std::to_string(k + 100), scaled_scene(std::ldexp(1.0, k)));
    EXPECT_EQ(p.rgb, unit.rgb) << "scale 2^" << k;
    EXPECT_TRUE(p.depth == unit.depth) << "scale 2^" << k;
  }
}

TEST(Range, TheNarrowestFieldOfViewRenders) {
  // At 1e-9 degrees the sphere's centre fills the picture: every pixel drawn, none lost.
  const Picture p = render("fov", scaled_scene(1, 1e-9));
  EXPECT_EQ(p.pixels, 40u * 30u);
}

TEST(Range, JustOutsideIsRefusedNamingTheField) {
  const std::string eye =
      refusal("eye", R"({"camera":{"eye":[0,0,1.9e19],"target":[0,0,0]},"objects":["cube"]})");
  EXPECT_NE(eye.find("camera.eye"), std::string::npos) << eye;
  EXPECT_NE(eye.find("zcube-range-"), std::string::npos) << eye; // the file
  EXPECT_NE(
      refusal("eye308", R"({"camera":{"eye":[1e308,0,5]},"objects":["cube"]})").find("camera.eye"),
      std::string::npos);
  const std::string fov = refusal("fov", scaled_scene(1, 0.9e-9));
  EXPECT_NE(fov.find("camera.fov"), std::string::npos) << fov;
  EXPECT_NE(refusal("fov37", scaled_scene(1, 1e-37)).find("camera.fov"), std::string::npos);
  const std::string vertex = refusal("vertex", R"({"camera":{"eye":[0,0,5]},"objects":["sphere",
                {"type":"cube","transform":{"scale":1e38}}]})");
  EXPECT_NE(vertex.find("of object 1 (cube)"), std::string::npos) << vertex;
  const std::string tiny = refusal("tiny", scaled_scene(std::ldexp(1.0, -68)));
  EXPECT_NE(tiny.find("camera"), std::string::npos) << tiny;
  EXPECT_EQ(refusal("inside", scaled_scene(std::ldexp(1.0, 61))), "");
}
