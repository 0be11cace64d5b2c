#pragma once
// What the build knows of itself, generated at build time (cmake/build_info.cmake): zcube's version
// (CMake's project VERSION) and the commit it was built from ("unknown" outside a git checkout,
// "-dirty" appended when tracked files differed from it).
namespace zc::build_info {
extern const char* const kZcubeVersion;
extern const char* const kZcubeCommit;
} // namespace zc::build_info
