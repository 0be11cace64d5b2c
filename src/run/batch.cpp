#include "run/batch.hpp"

#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>

#include "util/fork_pipe.hpp"

namespace zc {

namespace {

struct Child {
  pid_t pid = -1;
  int fd = -1;
  std::size_t index = 0;
  std::string out;
};

// In the child: run, write the report (or the error) to fd, exit without running the parent's
// atexit handlers or flushing its buffers twice.
[[noreturn]] void child_main(const PointRunner& run_point, const SimConfig& cfg, int fd) {
  std::string out;
  try {
    out = run_point(cfg).dump();
  } catch (const std::exception& ex) {
    out = nlohmann::json{{"status", "error"}, {"error", ex.what()}}.dump();
  }
  std::size_t off = 0;
  while (off < out.size()) {
    const ssize_t n = write(fd, out.data() + off, out.size() - off);
    if (n <= 0) break;
    off += std::size_t(n);
  }
  close(fd);
  _exit(0);
}

nlohmann::json finish(Child& c) {
  close(c.fd);
  int status = 0;
  while (waitpid(c.pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!c.out.empty()) {
    try {
      return nlohmann::json::parse(c.out);
    } catch (const std::exception&) {
    }
  }
  std::string why = WIFSIGNALED(status)
                        ? std::string("killed by signal ") + strsignal(WTERMSIG(status))
                        : "exit status " + std::to_string(WEXITSTATUS(status));
  return {{"status", "error"}, {"error", "simulation process died (" + why + ")"}};
}

// Ctrl-C (SIGINT), SIGTERM or SIGHUP (the terminal closed) while a batch runs: the parent kills
// its children (SIGKILL: a child interrupted in SimGrid's or a library's exit path can hang
// there), reaps them, and dies of the same signal, so no simulation outlives `zcube sweep` or
// `zcube reproduce`. A child whose parent dies otherwise (SIGKILL) is killed by the kernel.
volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int sig) {
  g_stop_signal = sig;
}

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};

struct StopSignals {
  struct sigaction old[3] = {};
  StopSignals() {
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < 3; ++i) {
      sigaction(kStopSignals[i], &sa, &old[i]);
      // A signal the caller ignores (nohup, a background job) stays ignored.
      if (old[i].sa_handler == SIG_IGN) sigaction(kStopSignals[i], &old[i], nullptr);
    }
  }
  ~StopSignals() {
    for (int i = 0; i < 3; ++i)
      sigaction(kStopSignals[i], &old[i], nullptr);
  }
};

[[noreturn]] void stop_batch(std::vector<Child>& running) {
  for (const Child& c : running)
    kill(c.pid, SIGKILL);
  for (Child& c : running) {
    close(c.fd);
    while (waitpid(c.pid, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  const int sig = g_stop_signal;
  signal(sig, SIG_DFL);
  raise(sig);
  _exit(128 + sig);
}

} // namespace

int default_jobs() {
  return std::max(1, int(std::thread::hardware_concurrency()));
}

std::vector<nlohmann::json> run_batch(const std::vector<SimConfig>& points, int jobs,
                                      const PointRunner& run_point,
                                      const std::function<void(const BatchProgress&)>& progress) {
  std::vector<nlohmann::json> reports(points.size());
  std::vector<Child> running;
  BatchProgress pr;
  pr.total = points.size();
  std::size_t next = 0;
  jobs = std::max(1, jobs);
  g_stop_signal = 0;
  const StopSignals stop_signals;
  while (next < points.size() || !running.empty()) {
    if (g_stop_signal) stop_batch(running);
    while (next < points.size() && int(running.size()) < jobs) {
      const pid_t parent = getpid();
      const PipedChild child = fork_with_pipe();
      if (child.pid == 0) {
        for (const int sig : kStopSignals) // the parent's handler is for the parent
          signal(sig, SIG_DFL);
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent) _exit(1); // the parent died before prctl
        for (const Child& c : running)
          close(c.fd);
        child_main(run_point, points[next], child.fd);
      }
      running.push_back({child.pid, child.fd, next, {}});
      ++next;
    }
    std::vector<pollfd> pfd;
    for (const Child& c : running)
      pfd.push_back({c.fd, POLLIN, 0});
    if (poll(pfd.data(), pfd.size(), 250) < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("poll failed");
    }
    for (std::size_t i = running.size(); i-- > 0;) {
      if (!(pfd[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      char buf[65536];
      const ssize_t n = read(running[i].fd, buf, sizeof buf);
      if (n > 0) {
        running[i].out.append(buf, std::size_t(n));
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      nlohmann::json rep = finish(running[i]);
      if (rep.value("status", "error") == "error") ++pr.failed;
      reports[running[i].index] = std::move(rep);
      running.erase(running.begin() + std::ptrdiff_t(i));
      ++pr.done;
      if (progress) progress(pr);
    }
  }
  return reports;
}

} // namespace zc
