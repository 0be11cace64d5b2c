#include "repro/background_job.hpp"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>
#include <stdexcept>

#include "util/fork_pipe.hpp"

namespace zc {

namespace {

void write_all(int fd, const std::string& s) {
  for (std::size_t at = 0; at < s.size();) {
    const ssize_t n = write(fd, s.data() + at, s.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    at += std::size_t(n);
  }
}

// In the child: send its standard error to `err`, run, and exit without the parent's atexit
// handlers and destructors (the parent's plot process and scratch files are the parent's).
[[noreturn]] void job_main(const std::function<void()>& work, std::FILE* err, int fd,
                           pid_t parent) {
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parent) _exit(1); // the parent died before prctl
  dup2(fileno(err), STDERR_FILENO);
  int status = 0;
  try {
    work();
  } catch (const std::exception& ex) {
    write_all(fd, ex.what());
    status = 1;
  } catch (...) {
    write_all(fd, "unknown error");
    status = 1;
  }
  std::fflush(nullptr);
  close(fd);
  _exit(status);
}

} // namespace

BackgroundJob::BackgroundJob(const std::function<void()>& work) {
  err_ = std::tmpfile(); // unlinked: gone with its last descriptor
  if (!err_) throw std::runtime_error("no temporary file for a background job");
  const pid_t parent = getpid();
  PipedChild child{};
  try {
    child = fork_with_pipe();
  } catch (...) {
    std::fclose(err_);
    throw;
  }
  if (child.pid == 0) job_main(work, err_, child.fd, parent);
  pid_ = child.pid;
  fd_ = child.fd;
}

BackgroundJob::~BackgroundJob() {
  if (pid_ > 0 && !ended_) {
    kill(pid_, SIGTERM);
    while (waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  if (fd_ >= 0) close(fd_);
  if (err_) std::fclose(err_);
}

bool BackgroundJob::finished() {
  if (!ended_ && pid_ > 0) ended_ = wait_child(pid_, &status_, WNOHANG, &cost_) == pid_;
  return ended_;
}

bool BackgroundJob::succeeded() const {
  return ended_ && WIFEXITED(status_) && WEXITSTATUS(status_) == 0;
}

std::string BackgroundJob::wait() {
  std::string error;
  char buf[4096];
  for (;;) {
    const ssize_t n = read(fd_, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    error.append(buf, std::size_t(n));
  }
  close(fd_);
  fd_ = -1;
  if (!ended_) wait_child(pid_, &status_, 0, &cost_);
  ended_ = true;
  const int status = status_;
  pid_ = -1;
  // Its standard error, after ours (the file's offset is shared with the child: rewind it).
  std::fflush(stderr);
  std::rewind(err_);
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, err_)) > 0;)
    std::fwrite(buf, 1, n, stderr);
  std::fflush(stderr);
  std::fclose(err_);
  err_ = nullptr;
  if (!error.empty()) return error;
  if (WIFSIGNALED(status)) return std::string("killed by signal ") + strsignal(WTERMSIG(status));
  if (WEXITSTATUS(status) != 0) return "exit status " + std::to_string(WEXITSTATUS(status));
  return "";
}

} // namespace zc
