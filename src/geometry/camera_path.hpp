#pragma once
// The camera path of an animation (Charles et al. §4: "a sequence of pictures for various
// observer's positions (rotation, zoom...)"): frame k of K orbits the eye about the target around
// the up axis by 360*k/K degrees while the distance breathes between 100% and 70%.
#include "geometry/camera.hpp"

namespace zc {

Camera camera_at_frame(const Camera& base, int frame, int frames);

} // namespace zc
