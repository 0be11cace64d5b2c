#include "util/stdout_result.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include "util/output_file.hpp"

namespace zc {

namespace {
int result_fd = -1; // the standard output kept for the result, once reserved
} // namespace

bool names_stdout(const std::string& path) {
  return path == "-" || path == "/dev/stdout" || path == "/dev/fd/1" || path == "/proc/self/fd/1";
}

void reserve_stdout_for_result() {
  if (result_fd >= 0) return;
  std::cout.flush();
  std::fflush(stdout);
  // Close-on-exec: the plot scripts and other children write to the new descriptor 1 only.
  result_fd = ::fcntl(1, F_DUPFD_CLOEXEC, 3);
  if (result_fd < 0 || ::dup2(2, 1) < 0)
    throw std::runtime_error(std::string("cannot keep standard output for the result: ") +
                             std::strerror(errno));
}

void write_result_to_stdout(const std::string& text) {
  std::cout.flush();
  std::fflush(stdout);
  const int fd = result_fd >= 0 ? result_fd : 1;
  // A reader that has gone (`| head`) is a failed write, not a signal that kills the command.
  struct sigaction ignore = {}, old = {};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &ignore, &old);
  int err = 0;
  for (std::size_t at = 0; at < text.size() && !err;) {
    const ssize_t n = ::write(fd, text.data() + at, text.size() - at);
    if (n < 0 && errno != EINTR) err = errno;
    if (n > 0) at += std::size_t(n);
  }
  sigaction(SIGPIPE, &old, nullptr);
  if (err)
    throw std::runtime_error(std::string("cannot write standard output: ") + std::strerror(err));
}

void write_result_file(const std::string& path, const std::string& text) {
  if (names_stdout(path))
    write_result_to_stdout(text);
  else
    write_text_file(path, text);
}

} // namespace zc
