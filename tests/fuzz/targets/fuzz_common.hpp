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

inline const std::string& temp_dir() {
  static const std::string dir = [] {
    std::string t = "/tmp/zcube-fuzz-XXXXXX";
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
