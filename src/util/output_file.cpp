#include "util/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/vfs.h>
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

// Why `path` (which exists and is not a regular file) cannot be an output: a FIFO or a socket
// found in the file system would block the write until a reader comes. A device (/dev/null) and
// a pipe this process was given (/dev/stdout under a shell pipe) are written in place.
std::string special_output_problem(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return "";
  if (S_ISSOCK(st.st_mode)) return "is a socket, not a file";
  if (!S_ISFIFO(st.st_mode)) return "";
  struct statfs fs {};
  constexpr long kPipeFs = 0x50495045; // an anonymous pipe, not a FIFO of the file system
  if (::statfs(path.c_str(), &fs) == 0 && long(fs.f_type) == kPipeFs) return "";
  return "is a FIFO: zcube writes its outputs to files (opening a FIFO waits for a reader)";
}

// Writes the file `tmp` to `path`, a device or a pipe, every write and the close checked.
void copy_to_device(const std::string& tmp, const std::string& path) {
  auto fail = [&](int err) {
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(err));
  };
  const int in = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) fail(errno);
  const int out = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NONBLOCK);
  if (out < 0) {
    const int err = errno;
    ::close(in);
    fail(err);
  }
  ::fcntl(out, F_SETFL, ::fcntl(out, F_GETFL) & ~O_NONBLOCK);
  char buf[1 << 16];
  int err = 0;
  for (ssize_t n; !err && (n = ::read(in, buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) err = errno;
    for (ssize_t at = 0; !err && at < n;) {
      const ssize_t w = ::write(out, buf + at, std::size_t(n - at));
      if (w < 0 && errno != EINTR) err = errno;
      if (w > 0) at += w;
    }
  }
  ::close(in);
  if (::close(out) != 0 && !err) err = errno;
  if (err) fail(err);
}

// A directory of this process's own under the system's temporary directory, removed with what it
// holds when the object goes.
struct PrivateDir {
  std::string path;
  PrivateDir() {
    std::string t = (fs::temp_directory_path() / "zcube-out-XXXXXX").string();
    if (!::mkdtemp(t.data())) throw std::runtime_error("cannot create a temporary directory");
    path = t;
  }
  ~PrivateDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

} // namespace

void check_output_path(const std::string& path, const std::string& flag) {
  if (path.empty()) return;
  // Not a file named "-": the flags that can write to standard output take it before this check
  // (util/stdout_result.hpp), and the others cannot.
  if (path == "-")
    throw UsageError(flag + " '-': this output is a file (only --report and platform's --output "
                            "take '-' for standard output)");
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw UsageError(flag + " '" + path + "': is a directory, not a file name");
  const fs::path dir = fs::path(path).parent_path();
  if (!dir.empty() && !fs::is_directory(dir, ec))
    throw UsageError(flag + " '" + path + "': directory '" + dir.string() + "' does not exist");
  // The file is replaced by a rename, so its directory must take a new file (tried, then
  // removed); a device such as /dev/null is written in place.
  const auto st = fs::status(path, ec);
  if (fs::exists(st) && !fs::is_regular_file(st)) {
    const std::string why = special_output_problem(path);
    if (!why.empty()) throw UsageError(flag + " '" + path + "': " + why);
    return;
  }
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

void write_file_atomically(const std::string& path_given,
                           const std::function<bool(const std::string& tmp)>& produce) {
  // A copy: `produce` may change the string `path_given` refers to (the Gantt charts' writer
  // hands each chart's temporary name on through it).
  const std::string path = path_given;
  std::error_code ec;
  fs::path target = path;
  if (fs::is_symlink(target, ec)) target = fs::weakly_canonical(target, ec); // keep the link
  const auto st = fs::status(target, ec);
  if (fs::exists(st) && !fs::is_regular_file(st)) { // a device or a pipe: nothing to replace
    const std::string why = special_output_problem(path);
    if (!why.empty()) throw std::runtime_error("cannot write '" + path + "': " + why);
    // Produced as a file first, then copied with every write checked: the writers' own
    // libraries do not all report a write that fails on a device (/dev/full).
    const PrivateDir dir;
    const std::string tmp =
        (fs::path(dir.path) / ("out" + fs::path(path).extension().string())).string();
    if (!produce(tmp)) throw std::runtime_error("cannot write '" + path + "'");
    copy_to_device(tmp, path);
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
