#pragma once
// The text of the data files under machines/, compiled into zcube by CMake (machine_data.cpp is
// generated in the build tree from cmake/machine_data.cpp.in; CMake globs the folders, so a new
// file is built in, and an edit of one rebuilds it). Compiled in, the binary needs no data folder.
#include <span>

namespace zc::machine_data {

struct DataFile {
  const char* path; // relative to the source tree: "machines/ipsc2.json"
  const char* text;
};

// machines/*.json, one built-in machine each, in file name order.
std::span<const DataFile> machine_files();
// machines/cpu/*.json but operations.json: one CPU model each, in file name order.
std::span<const DataFile> cpu_files();
// machines/cpu/operations.json: the instruction mix of every counted operation.
extern const char* const kOperations;

} // namespace zc::machine_data
