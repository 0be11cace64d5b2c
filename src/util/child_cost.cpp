#include "util/child_cost.hpp"

#include <sys/resource.h>
#include <sys/wait.h>

#include <cerrno>

namespace zc {

namespace {

ChildCost cost_of(const struct rusage& ru) {
  ChildCost c;
  c.user_s = double(ru.ru_utime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec);
  c.system_s = double(ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_stime.tv_usec);
  c.minor_faults = ru.ru_minflt;
  return c;
}

} // namespace

pid_t wait_child(pid_t pid, int* status, int options, ChildCost* cost) {
  struct rusage ru {};
  pid_t got = 0;
  while ((got = wait4(pid, status, options, &ru)) < 0 && errno == EINTR) {
  }
  if (got == pid && cost) *cost = cost_of(ru);
  return got;
}

ChildCost own_cost() {
  struct rusage ru {};
  getrusage(RUSAGE_SELF, &ru);
  return cost_of(ru);
}

ChildCost reaped_cost() {
  struct rusage ru {};
  getrusage(RUSAGE_CHILDREN, &ru);
  return cost_of(ru);
}

} // namespace zc
