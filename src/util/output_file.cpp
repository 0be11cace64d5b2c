#include "util/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "util/error.hpp"

namespace zc {

void check_output_path(const std::string& path, const std::string& flag) {
  if (path.empty()) return;
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw UsageError(flag + " '" + path + "': is a directory, not a file name");
  const fs::path dir = fs::path(path).parent_path();
  if (!dir.empty() && !fs::is_directory(dir, ec))
    throw UsageError(flag + " '" + path + "': directory '" + dir.string() + "' does not exist");
}

void prepare_output_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw UsageError("--out " + dir + ": exists and is not a directory");
  fs::create_directories(dir, ec);
  if (ec) throw UsageError("--out " + dir + ": cannot create the directory (" + ec.message() + ")");
}

void write_text_file(const std::string& path, const std::string& text) {
  auto fail = [&](int err) {
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(err));
  };
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) fail(errno);
  const bool wrote = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  const int write_err = errno;
  const bool flushed = std::fflush(f) == 0;
  const int flush_err = errno;
  const bool closed = std::fclose(f) == 0;
  if (!wrote) fail(write_err);
  if (!flushed) fail(flush_err);
  if (!closed) fail(errno);
}

} // namespace zc
