#include "util/image_module.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "util/error.hpp"
#include "util/error_text.hpp"
#include "util/output_file.hpp"

namespace zc::image_module {

namespace {

using WriteFn = int (*)(const char*, int, int, int, int, const void*, char*, unsigned long);
using ReadFn = int (*)(const char*, int*, int*, int*, unsigned char**, char*, unsigned long);

struct Module {
  WriteFn write = nullptr;
  ReadFn read = nullptr;
};

// Beside the executable (the build tree), else in ../lib/zcube (an installed tree).
const Module& module() {
  static const Module m = [] {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path exe_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
    const char* name = "zcube_image.so";
    std::string tried, why = "missing symbols";
    for (const fs::path& p : {exe_dir / name, exe_dir / ".." / "lib" / "zcube" / name}) {
      // RTLD_LOCAL: OpenImageIO's dependencies stay out of the global symbol scope.
      if (void* h = dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL)) {
        Module mod{reinterpret_cast<WriteFn>(dlsym(h, "zcube_image_write")),
                   reinterpret_cast<ReadFn>(dlsym(h, "zcube_image_read"))};
        if (mod.write && mod.read) return mod;
      }
      if (const char* e = dlerror()) why = e; // read once: a second call returns null
      tried += (tried.empty() ? "" : ", ") + p.string();
    }
    throw std::runtime_error("image support not available: cannot load " + tried + " (" + why +
                             ")");
  }();
  return m;
}

} // namespace

void write(const std::string& path, int width, int height, int channels, bool is_float,
           const void* data) {
  char err[512] = "";
  write_file_atomically(path, [&](const std::string& tmp) {
    if (module().write(tmp.c_str(), width, height, channels, is_float ? 1 : 0, data, err,
                       sizeof err) != 0)
      throw std::runtime_error(path + ": cannot write image: " + one_line(err));
    return true;
  });
}

namespace {

// The image libraries under OpenImageIO (libpng) print their own warnings and errors on stderr,
// a line before zcube's one-line error: stderr is sent to /dev/null while a file is decoded (the
// reason comes back through OpenImageIO's error text).
struct QuietStderr {
  int saved = -1;
  QuietStderr() {
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null < 0) return;
    std::fflush(stderr);
    saved = ::dup(STDERR_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::close(null);
  }
  ~QuietStderr() {
    if (saved < 0) return;
    std::fflush(stderr);
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
  }
};

} // namespace

ReadStatus read(const std::string& path, Pixels& out, std::string& error) {
  char err[512] = "";
  unsigned char* px = nullptr;
  int rc = 0;
  {
    const QuietStderr quiet;
    rc = module().read(path.c_str(), &out.width, &out.height, &out.channels, &px, err, sizeof err);
  }
  error = one_line(err);
  if (rc != 0) return ReadStatus(rc);
  const std::size_t n =
      std::size_t(out.width) * std::size_t(out.height) * std::size_t(out.channels);
  out.data.assign(px, px + n);
  std::free(px);
  return ReadStatus::Ok;
}

} // namespace zc::image_module
