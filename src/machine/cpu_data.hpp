#pragma once
// The text of machines/cpu/*.json, compiled into zcube by CMake (cpu_data.cpp is generated in the
// build tree from cmake/cpu_data.cpp.in, so an edit of a data file rebuilds it).
namespace zc::cpu_data {
extern const char* const kOperations; // machines/cpu/operations.json
extern const char* const kI80386;     // machines/cpu/i80386.json
extern const char* const kI860XR;     // machines/cpu/i860xr.json
} // namespace zc::cpu_data
