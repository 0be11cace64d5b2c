// The fixed-point set-up at the edges of the float range: vertices whose clip-space
// values overflow are dropped, never turned into undefined 64-bit arithmetic (UBSan found a signed
// overflow in the edge products for z = -3.4e38), and the rest of the picture is unaffected.
#include <gtest/gtest.h>

#include "raster/image_io.hpp"
#include "raster/renderer.hpp"
#include "raster_fixtures.hpp"

using namespace zc;
using namespace zc::test;

TEST(SetupRange, VerticesNearFloatMaxAreDroppedSafely) {
  Scene s = base_scene(32, 24);
  s.vertices = {{{-1, -1, -3}, {0, 0, 1}},    {{1, -1, -3}, {0, 0, 1}},
                {{0, 1, -3}, {0, 0, 1}},      {{0, 0, -3.4e38f}, {0, 0, 1}},
                {{1, 0, 3.4e38f}, {0, 0, 1}}, {{-3.4e38f, 3.4e38f, -2}, {0, 0, 1}}};
  s.triangles = {Triangle{{0, 1, 2}, 0}, Triangle{{3, 4, 5}, 0}, Triangle{{0, 1, 3}, 0}};
  auto r = render_scene(s, 1);
  Scene alone = s;
  alone.triangles = {Triangle{{0, 1, 2}, 0}};
  auto a = render_scene(alone, 1);
  EXPECT_GT(a.counters.pixels_final, 0u);
  EXPECT_EQ(image_sha256(r.image), image_sha256(render_scene(s, 3).image));
}
