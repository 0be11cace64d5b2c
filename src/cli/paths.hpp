#pragma once
// Where the source tree's data (scenes/, platforms/, scripts/, results/) is: the current directory
// when it is a zcube checkout, else the tree this binary was built from.
#include <filesystem>
#include <string>

namespace zc::cli {

inline std::string source_root() {
  if (std::filesystem::exists("scenes/teapot.json") && std::filesystem::exists("src/cli"))
    return ".";
  return ZCUBE_SOURCE_DIR;
}

} // namespace zc::cli
