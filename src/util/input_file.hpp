#pragma once
// Input files are read only when they are regular files: a FIFO would block the read for ever, a
// directory or a device is not a file of data. One check, one wording per case.
#include <filesystem>
#include <string>

#include "util/error.hpp"

namespace zc {

// Empty when `path` is a regular file (or a link to one), else why it cannot be read: "not found",
// "is a directory, not a file", "is a FIFO, not a regular file (...)".
inline std::string input_file_problem(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) return "an empty file name";
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) return "not found";
  if (ec) return "cannot be read (" + ec.message() + ")";
  if (st.type() == fs::file_type::regular) return "";
  if (st.type() == fs::file_type::directory) return "is a directory, not a file";
  return std::string("is a ") + (st.type() == fs::file_type::fifo ? "FIFO" : "device or socket") +
         ", not a regular file (zcube reads regular files only)";
}

// InputError naming `path` unless it is a regular file: "file not found", "is a directory...".
inline void check_input_file(const std::string& path) {
  const std::string p = input_file_problem(path);
  if (p == "not found") throw InputError(path, 0, "file not found");
  if (!p.empty()) throw InputError(path, 0, p);
}

// The same problem, said by the file that refers to `path` as `what` ("texture file not found:
// t.png", "mesh file t.obj: is a FIFO, ..."); empty when `path` is a regular file.
inline std::string referenced_file_problem(const std::string& what, const std::string& path) {
  const std::string p = input_file_problem(path);
  if (p.empty()) return p;
  return p == "not found" ? what + " not found: " + path : what + " " + path + ": " + p;
}

} // namespace zc
