#include "run/image_check.hpp"

#include <algorithm>
#include <map>

#include "geometry/camera_path.hpp"
#include "raster/image_io.hpp"
#include "raster/renderer.hpp"

namespace zc {

ReferenceFrame reference_frame(const Scene& scene, int frame, int frames) {
  Scene sf = scene;
  sf.camera = camera_at_frame(scene.camera, frame, frames);
  const Framebuffer seq = render_scene(sf, 1).image;
  return {image_sha256(seq), depth_map(seq)};
}

std::vector<Framebuffer> assemble_frames(std::vector<FrameImage> images, const Scene& scene) {
  std::map<int, Framebuffer> composed;
  std::vector<FrameImage> whole;
  for (auto& fi : images) {
    if (!fi.partial) {
      whole.push_back(std::move(fi));
      continue;
    }
    auto it = composed.find(fi.frame);
    if (it == composed.end())
      it = composed
               .emplace(fi.frame,
                        Framebuffer(scene.width, RowSet::all(scene.height), scene.background))
               .first;
    it->second.paste(fi.image);
  }
  for (auto& [f, fb] : composed)
    whole.push_back({f, std::move(fb)});
  std::sort(whole.begin(), whole.end(),
            [](const FrameImage& a, const FrameImage& b) { return a.frame < b.frame; });
  std::vector<Framebuffer> out;
  for (auto& fi : whole)
    out.push_back(std::move(fi.image));
  return out;
}

ImageVerdict check_images(const std::vector<Framebuffer>& frames, const Scene& scene,
                          const ImageCheck& how) {
  ImageVerdict v;
  v.checked = true;
  v.compared = how.compare;
  v.same_colour = v.same_depth = int(frames.size()) == how.expected_frames;
  for (int f = 0; f < int(frames.size()); ++f) {
    v.frames_sha256.push_back(image_sha256(frames[std::size_t(f)]));
    if (!how.compare) continue;
    const ReferenceFrame* drawn =
        how.lookup && *how.lookup ? (*how.lookup)(scene, f, how.expected_frames) : nullptr;
    const ReferenceFrame own =
        drawn ? ReferenceFrame{} : reference_frame(scene, f, how.expected_frames);
    const ReferenceFrame& ref = drawn ? *drawn : own;
    v.same_colour = v.same_colour && ref.sha256 == v.frames_sha256.back();
    v.same_depth = v.same_depth && same_depth_map(frames[std::size_t(f)], ref.depth);
  }
  return v;
}

namespace {
constexpr const char* kBoth = "colour and depth";
} // namespace

void to_json(nlohmann::json& j, const ImageVerdict& v) {
  j = nlohmann::json::object();
  if (!v.checked) return;
  const auto& shas = v.frames_sha256;
  j["sha256"] = shas.empty() ? nlohmann::json(nullptr) : nlohmann::json(shas.back());
  if (shas.size() > 1) j["frames_sha256"] = shas;
  j["identical_to_sequential"] =
      v.compared ? nlohmann::json(v.same_colour && v.same_depth) : nlohmann::json(nullptr);
  if (!v.compared) return;
  j["compared_with_sequential"] = kBoth;
  if (!v.same_colour || !v.same_depth)
    j["differs_from_sequential"] = !v.same_colour && !v.same_depth ? kBoth
                                   : !v.same_colour                ? "colour"
                                                                   : "depth";
}

void from_json(const nlohmann::json& j, ImageVerdict& v) {
  v = ImageVerdict{};
  v.checked = !j.empty();
  if (!v.checked) return;
  if (j.contains("frames_sha256"))
    v.frames_sha256 = j.at("frames_sha256").get<std::vector<std::string>>();
  else if (!j.at("sha256").is_null())
    v.frames_sha256 = {j.at("sha256").get<std::string>()};
  v.compared = j.contains("compared_with_sequential");
  const std::string differs = j.value("differs_from_sequential", "");
  v.same_colour = differs.empty() || differs == "depth";
  v.same_depth = differs.empty() || differs == "colour";
}

} // namespace zc
