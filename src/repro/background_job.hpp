#pragma once
// Work run in a forked process of its own beside the caller's: `zcube reproduce` runs the
// calibration (its own batches of simulations) while it runs the papers' batch, so that the cores
// stay busy through the calibration's steps (each a batch that ends on its slowest point) and the
// calibration's plot is drawn while the papers' simulations run.
#include <sys/types.h>

#include <cstdio>
#include <functional>
#include <string>

#include "util/child_cost.hpp"

namespace zc {

class BackgroundJob {
public:
  // Forks a process that runs `work`. Its standard error (and its children's) is held in a file
  // and copied to ours by wait(), so its lines do not cut into the caller's progress line. The
  // process dies with the caller (SIGTERM).
  explicit BackgroundJob(const std::function<void()>& work);
  ~BackgroundJob(); // a job not waited for is stopped (SIGTERM) and reaped
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;
  // Whether the job has ended (without waiting); wait() then returns at once.
  bool finished();
  // Whether it ended well (exit status 0), once finished.
  bool succeeded() const;
  // Waits for the job and copies its standard error to ours; the error that stopped it, or "".
  std::string wait();
  // What the job (with the simulations it forked) cost the host, once it has ended.
  const ChildCost& cost() const { return cost_; }

private:
  pid_t pid_ = -1;
  bool ended_ = false; // reaped by finished(), its exit status in status_
  int status_ = 0;
  ChildCost cost_;
  int fd_ = -1;              // the child's error text, if it throws
  std::FILE* err_ = nullptr; // its standard error
};

} // namespace zc
