// run/image_check: the pictures a run handed over, pasted into frames and checked against the
// sequential renderer's through the lookup the run was given; in process, without a simulation.
#include <gtest/gtest.h>

#include "raster/renderer.hpp"
#include "run/image_check.hpp"
#include "scene/load.hpp"

using namespace zc;

namespace {

Scene small_scene() {
  LoadOptions lo;
  lo.width = lo.height = 48;
  return load_scene(std::string(ZCUBE_SOURCE_DIR) + "/scenes/kurc/1pot.json", lo);
}

} // namespace

TEST(ImageCheck, RowsPastedTogetherEqualTheSequentialPicture) {
  const Scene s = small_scene();
  const Framebuffer whole = render_scene(s, 1).image;
  std::vector<FrameImage> delivered;
  for (int part = 0; part < 3; ++part) { // interleaved rows, as a deal hands them over
    Framebuffer rows(s.width, RowSet{part, s.height, 3}, s.background);
    rows.paste(whole);
    delivered.push_back({0, std::move(rows), true});
  }
  const auto frames = assemble_frames(std::move(delivered), s);
  ASSERT_EQ(frames.size(), 1u);
  const ImageVerdict v = check_images(frames, s, ImageCheck{true, 1, nullptr});
  EXPECT_TRUE(v.same_colour && v.same_depth);
  EXPECT_EQ(nlohmann::json(v)["identical_to_sequential"], true);
}

TEST(ImageCheck, TheLookupsReferenceIsUsedAndAWrongOneIsADifference) {
  const Scene s = small_scene();
  const std::vector<Framebuffer> frames = {render_scene(s, 1).image};
  ReferenceFrame wrong = reference_frame(s, 0, 1);
  wrong.sha256 = "not the picture";
  int looked_up = 0;
  const ReferenceLookup lookup = [&](const Scene&, int, int) {
    ++looked_up;
    return &wrong;
  };
  const ImageVerdict v = check_images(frames, s, ImageCheck{true, 1, &lookup});
  EXPECT_EQ(looked_up, 1);
  EXPECT_FALSE(v.same_colour);
  EXPECT_TRUE(v.same_depth);
  const nlohmann::json j = v;
  EXPECT_EQ(j["differs_from_sequential"], "colour");
  // The verdict travels in a recorded trace and comes back the same.
  EXPECT_EQ(nlohmann::json(j.get<ImageVerdict>()), j);
}

TEST(ImageCheck, MissingFramesAndBenchmarks) {
  const Scene s = small_scene();
  const std::vector<Framebuffer> one = {render_scene(s, 1).image};
  const ImageVerdict short_of_frames = check_images(one, s, ImageCheck{true, 2, nullptr});
  EXPECT_EQ(nlohmann::json(short_of_frames)["identical_to_sequential"], false);
  const ImageVerdict benchmark = check_images({}, s, ImageCheck{false, 1, nullptr});
  const nlohmann::json j = benchmark;
  EXPECT_TRUE(j["sha256"].is_null());
  EXPECT_TRUE(j["identical_to_sequential"].is_null());
  EXPECT_EQ(nlohmann::json(j.get<ImageVerdict>()), j);
}
