#pragma once
// The pictures a run handed over, pasted into frames and checked against the sequential
// renderer's (colour and depth): the report's "image".
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "raster/framebuffer.hpp"
#include "run/node_record.hpp"
#include "scene/scene.hpp"

namespace zc {

// What an image is compared with: the sequential renderer's picture of a scene at one frame of a
// run of `frames` frames, as its colour hash and its depth map.
struct ReferenceFrame {
  std::string sha256;
  std::vector<float> depth;
};
ReferenceFrame reference_frame(const Scene& scene, int frame, int frames);
// Where a run finds a reference already drawn (a batch draws each once before it forks: repro/
// simulate.cpp): null when it has none, and then the check draws it itself.
using ReferenceLookup = std::function<const ReferenceFrame*(const Scene&, int frame, int frames)>;

// The delivered pictures as one picture per frame, in frame order: rows delivered straight to the
// output device (deliver_rows) are pasted together on the scene's background.
std::vector<Framebuffer> assemble_frames(std::vector<FrameImage> images, const Scene& scene);

// The frames' hashes and, when compared, whether colour and depth equal the sequential renderer's.
struct ImageVerdict {
  bool checked = false; // the run ended well and its pictures were looked at
  std::vector<std::string> frames_sha256;
  bool compared = false; // against the sequential renderer (not for a benchmark's non-picture)
  bool same_colour = true, same_depth = true;
};
// What to compare: `expected_frames` pictures, each with the sequential renderer's (looked up
// through `lookup` when it has one).
struct ImageCheck {
  bool compare = true;
  int expected_frames = 1;
  const ReferenceLookup* lookup = nullptr;
};
ImageVerdict check_images(const std::vector<Framebuffer>& frames, const Scene& scene,
                          const ImageCheck& how);

// The report's "image" (a recorded trace keeps it for its replays: run/call_trace.hpp).
void to_json(nlohmann::json& j, const ImageVerdict& v);
void from_json(const nlohmann::json& j, ImageVerdict& v);

} // namespace zc
