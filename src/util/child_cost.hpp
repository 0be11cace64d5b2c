#pragma once
// What a child process cost the host, as the kernel accounts it when the child is reaped (wait4):
// its CPU time in user space and in the kernel, and its minor page faults, with those of its own
// children that it reaped. Host measurements only: never part of a deterministic result.
#include <sys/types.h>

namespace zc {

struct ChildCost {
  double user_s = 0, system_s = 0;
  long minor_faults = 0;
  double cpu_s() const { return user_s + system_s; }
  ChildCost& operator+=(const ChildCost& o) {
    user_s += o.user_s;
    system_s += o.system_s;
    minor_faults += o.minor_faults;
    return *this;
  }
};

// waitpid(pid, status, options) that also gives the reaped child's cost (when it returns pid).
// Retries on EINTR; returns what waitpid returns.
pid_t wait_child(pid_t pid, int* status, int options, ChildCost* cost);

// This process's own cost so far (getrusage RUSAGE_SELF), and that of the children it has reaped
// with theirs (RUSAGE_CHILDREN).
ChildCost own_cost();
ChildCost reaped_cost();

} // namespace zc
