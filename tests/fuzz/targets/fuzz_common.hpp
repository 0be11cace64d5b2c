#pragma once
// Shared by the libFuzzer targets: each input is written to a file in a private temporary
// directory (the loaders take paths and dispatch on the extension) and loaded. An InputError is
// the expected answer to a bad file; any other exception, a crash, a sanitizer report, a hang or an
// allocation over libFuzzer's limit is a finding.
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

#include "util/error.hpp"

namespace zc::fuzz {

// The scene loaders' triangle budget under the fuzzer: 2^18 triangles tessellate in well under a
// second with AddressSanitizer, so a valid but huge scene (many recursion-9 spheres, at 4.4 s
// each) is refused at once instead of running into libFuzzer's per-input timeout.
constexpr std::uint64_t kTriangleBudget = std::uint64_t(1) << 18;

// Under $TMPDIR when it is set (ctest fuzz.quick sets it to a directory it removes), else /tmp.
inline const std::string& temp_dir() {
  static const std::string dir = [] {
    const char* base = std::getenv("TMPDIR");
    std::string t = std::string(base && *base ? base : "/tmp") + "/zcube-fuzz-XXXXXX";
    if (!mkdtemp(t.data())) std::abort();
    return t;
  }();
  return dir;
}

inline std::string write_input(const std::string& name, const std::uint8_t* data,
                               std::size_t size) {
  const std::string path = temp_dir() + "/" + name;
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

// Runs f, accepting only InputError (the loaders' one way to refuse a file).
template <class F> void expect_input_error_or_success(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  }
}

} // namespace zc::fuzz
