// geometry/camera and camera_path: the clip planes fitted around a scene, the projection's depth
// range, and the camera path of an animation (Charles et al. §4).
#include <cmath>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "geometry/camera.hpp"
#include "geometry/camera_path.hpp"

using namespace zc;

TEST(Camera, FittedPlanesHoldTheSceneAndTheProjectionMapsThemToMinusOneAndOne) {
  Bounds b;
  b.add({-1, -1, -1});
  b.add({1, 1, 1});
  Camera cam;
  cam.eye = {0, 0, 10};
  double n = 0, f = 0;
  resolve_clip_planes(cam, b, n, f);
  ASSERT_GT(n, 0);
  ASSERT_GT(f, n);
  const double d = glm::length(cam.eye - b.center());
  EXPECT_LE(n, d - b.radius()) << "the near plane in front of the bounding sphere";
  EXPECT_GE(f, d + b.radius()) << "the far plane behind it";
  const glm::dmat4 pv = projection_matrix(cam, 1.0, n, f) * view_matrix(cam);
  const glm::dvec4 near_pt = pv * glm::dvec4(0, 0, 10 - n, 1);
  const glm::dvec4 far_pt = pv * glm::dvec4(0, 0, 10 - f, 1);
  EXPECT_NEAR(near_pt.z / near_pt.w, -1.0, 1e-12);
  EXPECT_NEAR(far_pt.z / far_pt.w, 1.0, 1e-12);
}

TEST(Camera, GivenPlanesAreKept) {
  Camera cam;
  cam.znear = 0.5;
  cam.zfar = 50;
  Bounds b;
  b.add({0, 0, 0});
  double n = 0, f = 0;
  resolve_clip_planes(cam, b, n, f);
  EXPECT_EQ(n, 0.5);
  EXPECT_EQ(f, 50);
}

TEST(CameraPath, FrameZeroIsTheBaseAndTheOrbitKeepsTheTargetAndHeight) {
  Camera base;
  base.eye = {3, 2, 4};
  base.target = {1, 2, 1};
  const Camera first = camera_at_frame(base, 0, 8);
  EXPECT_NEAR(glm::length(first.eye - base.eye), 0, 1e-12);
  const double d0 = glm::length(base.eye - base.target);
  for (int k = 1; k < 8; ++k) {
    const Camera c = camera_at_frame(base, k, 8);
    EXPECT_EQ(c.target, base.target);
    EXPECT_NEAR(c.eye.y, base.eye.y, 1e-9) << "an orbit about the up axis, frame " << k;
    const double d = glm::length(c.eye - c.target);
    EXPECT_LE(d, d0 * (1 + 1e-12)) << "frame " << k;
    EXPECT_GE(d, 0.7 * d0 * (1 - 1e-12)) << "the distance breathes between 100 % and 70 %";
  }
}
