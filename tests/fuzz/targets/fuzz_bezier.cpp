// libFuzzer target: Newell's Bezier patch files, both forms (src/scene/bezier.cpp), parsed and
// tessellated. The first byte chooses the form (.bpt or teaset).
#include "fuzz_common.hpp"
#include "scene/bezier.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string path = (data[0] & 1) ? "in.bpt" : "teaset";
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  zc::fuzz::expect_input_error_or_success([&] {
    const auto patches = zc::parse_bezier(text, path);
    zc::tessellate_patches(patches, 4);
  });
  return 0;
}
