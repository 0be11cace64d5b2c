#include "util/output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "util/error.hpp"

namespace zc {

namespace fs = std::filesystem;

namespace {

// Beside the target, hidden, unique to this process and call, with the target's extension.
std::string temporary_beside(const fs::path& target) {
  static std::atomic<unsigned> serial{0};
  // Appended piecewise: GCC 12 -O3 reports a false -Wrestrict on a chain of operator+.
  std::string name = ".";
  name.append(target.stem().string()).append(".zcube-").append(std::to_string(getpid()));
  name.append("-").append(std::to_string(serial++)).append(target.extension().string());
  return (target.parent_path() / name).string();
}

} // namespace

void check_output_path(const std::string& path, const std::string& flag) {
  if (path.empty()) return;
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw UsageError(flag + " '" + path + "': is a directory, not a file name");
  const fs::path dir = fs::path(path).parent_path();
  if (!dir.empty() && !fs::is_directory(dir, ec))
    throw UsageError(flag + " '" + path + "': directory '" + dir.string() + "' does not exist");
  // The file is replaced by a rename, so its directory must take a new file (tried, then
  // removed); a device such as /dev/null is written in place.
  const auto st = fs::status(path, ec);
  if (fs::exists(st) && !fs::is_regular_file(st)) return;
  const std::string probe = temporary_beside(path);
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0)
    throw UsageError(flag + " '" + path + "': cannot create a file in '" +
                     (dir.empty() ? std::string(".") : dir.string()) + "' (" +
                     std::strerror(errno) + ")");
  ::close(fd);
  ::unlink(probe.c_str());
}

void check_output_paths(const std::vector<std::pair<std::string, std::string>>& flag_paths) {
  for (std::size_t i = 0; i < flag_paths.size(); ++i) {
    const auto& [flag, path] = flag_paths[i];
    check_output_path(path, flag);
    if (path.empty()) continue;
    for (std::size_t k = 0; k < i; ++k) {
      const auto& [other_flag, other] = flag_paths[k];
      if (other.empty()) continue;
      std::error_code ec;
      const bool same = fs::weakly_canonical(path, ec) == fs::weakly_canonical(other, ec) ||
                        fs::equivalent(path, other, ec);
      if (same)
        throw UsageError(flag + " '" + path + "': the same file as " + other_flag + " '" + other +
                         "' (each output needs a file of its own)");
    }
  }
}

void check_image_path(const std::string& path, const std::string& flag) {
  if (path.empty()) return;
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const char* known :
       {".png", ".exr", ".tif", ".tiff", ".jpg", ".jpeg", ".bmp", ".ppm", ".pnm", ".tga", ".hdr"})
    if (ext == known) return;
  throw UsageError(flag + " '" + path +
                   "': not an image file name (.png, .exr, .tif, .tiff, .jpg, .jpeg, .bmp, .ppm, "
                   ".pnm, .tga or .hdr)");
}

void prepare_output_dir(const std::string& dir, const std::string& flag) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw UsageError(flag + " " + dir + ": exists and is not a directory");
  fs::create_directories(dir, ec);
  if (ec)
    throw UsageError(flag + " " + dir + ": cannot create the directory (" + ec.message() + ")");
  check_output_path((fs::path(dir) / "x").string(), flag); // it takes new files
}

void write_file_atomically(const std::string& path,
                           const std::function<bool(const std::string& tmp)>& produce) {
  std::error_code ec;
  fs::path target = path;
  if (fs::is_symlink(target, ec)) target = fs::weakly_canonical(target, ec); // keep the link
  const auto st = fs::status(target, ec);
  if (fs::exists(st) && !fs::is_regular_file(st)) { // a device or a FIFO: nothing to replace
    if (!produce(path)) throw std::runtime_error("cannot write '" + path + "'");
    return;
  }
  const std::string tmp = temporary_beside(target);
  try {
    if (!produce(tmp)) throw std::runtime_error("cannot write '" + path + "'");
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error("cannot write '" + path + "': " + ec.message());
  }
}

void write_text_file(const std::string& path, const std::string& text) {
  write_file_atomically(path, [&](const std::string& tmp) {
    auto fail = [&](int err) {
      throw std::runtime_error("cannot write '" + path + "': " + std::strerror(err));
    };
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) fail(errno);
    const bool wrote = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    const int write_err = errno;
    const bool flushed = std::fflush(f) == 0;
    const int flush_err = errno;
    const bool closed = std::fclose(f) == 0;
    if (!wrote) fail(write_err);
    if (!flushed) fail(flush_err);
    if (!closed) fail(errno);
    return true;
  });
}

} // namespace zc
