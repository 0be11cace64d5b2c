#include "util/fork_pipe.hpp"

#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace zc {

PipedChild fork_with_pipe() {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    throw std::runtime_error("fork failed");
  }
  if (pid == 0) {
    close(fds[0]);
    return {0, fds[1]};
  }
  close(fds[1]);
  return {pid, fds[0]};
}

} // namespace zc
