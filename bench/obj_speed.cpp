// Host benchmark of the OBJ loader (not a test: it measures, it checks nothing): MB/s of
// zc::load_scene on a mesh file, against reading the same bytes from the page cache (disk speed
// once cached). Every load repeats until at least 1 s; the median is reported.
//   build/zcube_obj_speed [scenes/skull/headsq_bone_iso1150.obj ...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/load.hpp"

namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

template <class F> double median_s(F&& f) {
  std::vector<double> t;
  const double start = now_s();
  while (t.size() < 5 || now_s() - start < 1.0) {
    const double t0 = now_s();
    f();
    t.push_back(now_s() - t0);
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files(argv + 1, argv + argc);
  if (files.empty()) files = {ZCUBE_SOURCE_DIR "/scenes/skull/headsq_bone_iso1150.obj"};
  std::printf("%-40s %8s %10s %10s %12s\n", "file", "MB", "read MB/s", "load MB/s", "triangles");
  for (const auto& f : files) {
    const double mb = double(std::filesystem::file_size(f)) / 1e6;
    std::size_t sink = 0, tris = 0;
    const double read = median_s([&] {
      std::string bytes(std::filesystem::file_size(f), '\0');
      std::FILE* in = std::fopen(f.c_str(), "rb");
      if (in) {
        sink += std::fread(bytes.data(), 1, bytes.size(), in);
        std::fclose(in);
      }
    });
    const double load = median_s([&] { tris = zc::load_scene(f).triangles.size(); });
    std::printf("%-40s %8.2f %10.0f %10.1f %12zu\n",
                std::filesystem::path(f).filename().string().c_str(), mb, mb / read, mb / load,
                tris + 0 * sink);
  }
}
