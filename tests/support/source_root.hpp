#pragma once
// The source tree the tests read scenes, platforms and committed results from (one definition for
// the files a unity build compiles together).
#include <string>

namespace zc::test {
inline const std::string kRoot = ZCUBE_SOURCE_DIR;
} // namespace zc::test
