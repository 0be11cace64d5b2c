#pragma once
// A child process with a pipe to its parent, for work run in a process of its own (a batch's
// simulations, a trial of SimGrid settings): the parent reads what the child writes.
#include <sys/types.h>

namespace zc {

// In the parent: the child's pid and the pipe's read end. In the child: pid 0 and the write end.
// Buffered output is flushed first, so it is not written twice. std::runtime_error on failure.
struct PipedChild {
  pid_t pid;
  int fd;
};
PipedChild fork_with_pipe();

} // namespace zc
