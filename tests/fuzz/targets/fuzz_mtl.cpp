// libFuzzer target: MTL material libraries (src/scene/obj.cpp), pulled in by a fixed OBJ.
#include "fuzz_common.hpp"
#include "scene/load.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char obj[] = "mtllib in.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                            "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 2/2\n";
  static const std::string obj_path =
      zc::fuzz::write_input("in.obj", reinterpret_cast<const std::uint8_t*>(obj), sizeof obj - 1);
  zc::fuzz::write_input("in.mtl", data, size);
  zc::fuzz::expect_input_error_or_success([&] {
    zc::load_scene(obj_path, {64, 64, zc::fuzz::kTriangleBudget});
  });
  return 0;
}
