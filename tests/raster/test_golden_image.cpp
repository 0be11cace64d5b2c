// Golden image of the default scene: any change to the renderer's output bits shows up here.
// If a change is intended, update the hash and say why in the commit.
#include <gtest/gtest.h>

#include "raster/image_io.hpp"
#include "raster/renderer.hpp"
#include "scene/load.hpp"

using namespace zc;

TEST(Golden, DefaultTeapotScene) {
  const Scene s = load_scene(std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json");
  ASSERT_EQ(s.triangles.size(), 3751u);
  const auto r1 = render_scene(s, 1);
  EXPECT_EQ(image_sha256(r1.image),
            "9319561ebfa3f8180d3177458c97c6df1ce2a8400b81abf24c7d7a1ee9dddb7b");
  EXPECT_EQ(r1.counters.pixels_generated, 152405u);
  EXPECT_EQ(r1.counters.pixels_final, 76064u);
  const auto r2 = render_scene(s, 2);
  EXPECT_EQ(image_sha256(r2.image), image_sha256(r1.image));
  EXPECT_EQ(r2.counters, r1.counters);
}
