// libFuzzer target: Blazek's scene description language (src/scene/sdl.cpp) through load_scene.
#include "fuzz_common.hpp"
#include "scene/load.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = zc::fuzz::write_input("in.sdl", data, size);
  zc::fuzz::expect_input_error_or_success([&] {
    zc::load_scene(path, {64, 64, zc::fuzz::kTriangleBudget});
  });
  return 0;
}
