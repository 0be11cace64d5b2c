#include "run/batch.hpp"

#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <functional>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include "util/child_cost.hpp"
#include "util/fork_pipe.hpp"
#include "util/huge_pages.hpp"

namespace zc {

namespace {

// A point's work in its child process: what it writes back to the parent.
struct Job {
  std::size_t index = 0;
  std::function<std::string()> work;
  int mode = 0; // the caller's (run_batch_replaying: full, record or replay)
};

struct Child {
  pid_t pid = -1;
  int fd = -1;
  Job job;
  std::string out;
};

// What a child writes to its pipe: the size of its report (8 bytes, the host's order), the report
// as CBOR (binary: no number is printed by the child nor read back by the parent, and every value
// comes back exactly), then, from a recording run, its trace.
using FrameSize = std::uint64_t; // the frame's header

std::string frame(const nlohmann::json& report) {
  const std::vector<std::uint8_t> cbor = nlohmann::json::to_cbor(report);
  const FrameSize n = cbor.size();
  std::string out(sizeof n, '\0');
  std::memcpy(out.data(), &n, sizeof n);
  return out.append(cbor.begin(), cbor.end());
}

// A point's report, or the error, framed for the pipe.
std::string report_frame(const std::function<nlohmann::json()>& run) {
  try {
    return frame(run());
  } catch (const std::exception& ex) {
    return frame({{"status", "error"}, {"error", ex.what()}});
  }
}

// In the child: run, write the output to fd, exit without running the parent's atexit handlers
// or flushing its buffers twice.
[[noreturn]] void child_main(const Job& job, int fd) {
  const std::string out = job.work(); // a report or the error (report_frame)
  std::size_t off = 0;
  while (off < out.size()) {
    const ssize_t n = write(fd, out.data() + off, out.size() - off);
    if (n <= 0) break;
    off += std::size_t(n);
  }
  close(fd);
  _exit(0);
}

// Where the child's report frame ends in its output (what follows is a trace), or npos when the
// output holds no whole frame.
std::size_t frame_end(const std::string& out) {
  FrameSize n = 0;
  if (out.size() < sizeof n) return std::string::npos;
  std::memcpy(&n, out.data(), sizeof n);
  return n <= out.size() - sizeof n ? sizeof n + std::size_t(n) : std::string::npos;
}

// The child's report, or why it gave none. A report's host section gains what the whole process
// cost the host (fork to exit: what the report's own wall time leaves out).
nlohmann::json finish(Child& c) {
  close(c.fd);
  int status = 0;
  ChildCost cost;
  wait_child(c.pid, &status, 0, &cost);
  if (const std::size_t end = frame_end(c.out); end != std::string::npos) {
    try {
      nlohmann::json rep = nlohmann::json::from_cbor(c.out.begin() + sizeof(FrameSize),
                                                     c.out.begin() + std::ptrdiff_t(end));
      if (rep.is_object() && rep.contains("host") && rep["host"].is_object()) {
        rep["host"]["process_cpu_s"] = cost.cpu_s();
        rep["host"]["process_kernel_s"] = cost.system_s;
        rep["host"]["process_minor_faults"] = cost.minor_faults;
      }
      return rep;
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

// The reports of a batch, held compactly while it runs (CBOR: a third of a parsed report's
// memory): every fork copies the page tables of the memory the parent holds, and the parent
// writing to pages a child shares copies them, so the parent's memory should not grow with the
// reports it has received. Unpacked, in order, once the batch is done (CBOR gives back every value
// exactly).
class PackedReports {
public:
  explicit PackedReports(std::size_t n) : packed_(n) {}
  void set(std::size_t i, const nlohmann::json& report) {
    packed_[i] = nlohmann::json::to_cbor(report);
  }
  std::vector<nlohmann::json> unpack() {
    std::vector<nlohmann::json> out(packed_.size());
    for (std::size_t i = 0; i < packed_.size(); ++i) {
      if (!packed_[i].empty()) out[i] = nlohmann::json::from_cbor(packed_[i]);
      std::vector<std::uint8_t>().swap(packed_[i]);
    }
    return out;
  }

private:
  std::vector<std::vector<std::uint8_t>> packed_;
};

} // namespace

int default_jobs() {
  return std::max(1, int(std::thread::hardware_concurrency()));
}

namespace {

// The next job to start (nullopt: none can start now), and what to do with a finished child.
using NextJob = std::function<std::optional<Job>()>;
using JobDone = std::function<void(Child&)>;

// Forks up to `jobs` children at a time until no job is left to start and none runs.
void run_jobs(int jobs, const NextJob& next, const JobDone& done) {
  std::vector<Child> running;
  jobs = std::max(1, jobs);
  g_stop_signal = 0;
  const StopSignals stop_signals;
  collapse_into_huge_pages(); // what the parent holds now: page tables each fork copies fast
  for (;;) {
    if (g_stop_signal) stop_batch(running);
    while (int(running.size()) < jobs) {
      std::optional<Job> job = next();
      if (!job) break;
      const pid_t parent = getpid();
      const PipedChild child = fork_with_pipe();
      if (child.pid == 0) {
        for (const int sig : kStopSignals) // the parent's handler is for the parent
          signal(sig, SIG_DFL);
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent) _exit(1); // the parent died before prctl
        for (const Child& c : running)
          close(c.fd);
        child_main(*job, child.fd);
      }
      running.push_back({child.pid, child.fd, std::move(*job), {}});
    }
    if (running.empty()) return;
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
      Child c = std::move(running[i]);
      running.erase(running.begin() + std::ptrdiff_t(i));
      done(c);
    }
  }
}

} // namespace

std::vector<nlohmann::json> run_batch(const std::vector<RunConfig>& points, int jobs,
                                      const PointRunner& run_point,
                                      const std::function<void(const BatchProgress&)>& progress) {
  PackedReports reports(points.size());
  BatchProgress pr;
  pr.total = points.size();
  std::size_t next = 0;
  const NextJob next_job = [&]() -> std::optional<Job> {
    if (next == points.size()) return std::nullopt;
    const RunConfig& cfg = points[next];
    return Job{next++, [&run_point, &cfg] { return report_frame([&] { return run_point(cfg); }); }};
  };
  run_jobs(jobs, next_job, [&](Child& c) {
    nlohmann::json rep = finish(c);
    if (rep.value("status", "error") == "error") ++pr.failed;
    reports.set(c.job.index, rep);
    ++pr.done;
    if (progress) progress(pr);
  });
  return reports.unpack();
}

namespace {

enum Mode { kFull, kRecord, kReplay };
constexpr const char* kDiverged = "zcube_replay_diverged";

// run_batch_replaying's bookkeeping in the parent: which points are left, which keys are being
// recorded, and what the finished children sent back.
class ReplaySchedule {
public:
  ReplaySchedule(const std::vector<RunConfig>& points, const ReplayRunner& runner,
                 TraceStore& traces)
      : points_(points), runner_(runner), traces_(traces) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      keys_.push_back(runner.key(points[i]));
      pending_.push_back({i, false});
    }
  }

  // The first pending point that can start: a replay when its key's trace is here, the recording
  // when nobody records its key yet, else a full run (no key, no trace possible, or diverged).
  std::optional<Job> next(bool idle) {
    for (auto it = pending_.begin(); it != pending_.end(); ++it) {
      const auto [i, full] = *it;
      const std::string& k = keys_[i];
      Mode m = kFull;
      if (!full && !k.empty() && !unreplayable_.contains(k)) {
        if (traces_.contains(k))
          m = kReplay;
        else if (!recording_.contains(k))
          m = kRecord;
        else if (!idle)
          continue; // its key's recording runs: wait for its trace
      }
      pending_.erase(it);
      if (m == kRecord) recording_.insert(k);
      return job(i, m);
    }
    return std::nullopt;
  }

  // A finished child: its report, or (a diverged replay) the point back in the queue for a full
  // run. Returns whether the point is done.
  bool done(Child& c, nlohmann::json& report) {
    const std::string& k = keys_[c.job.index];
    if (c.job.mode == kRecord) {
      recording_.erase(k);
      report = finish(c);
      const std::size_t end = frame_end(c.out);
      if (end != std::string::npos && end < c.out.size())
        traces_[k].assign(c.out.begin() + std::ptrdiff_t(end), c.out.end());
      else if (report.value("status", "") == "ok")
        unreplayable_.insert(k); // it ran well and left no trace: it read the clock
      ++counts.recorded;
      return true;
    }
    report = finish(c);
    if (c.job.mode == kReplay && report.contains(kDiverged)) {
      ++counts.diverged;
      pending_.push_front({c.job.index, true});
      return false;
    }
    ++(c.job.mode == kReplay ? counts.replayed : counts.full);
    return true;
  }

  ReplayCounts counts;

private:
  Job job(std::size_t i, Mode m) {
    const RunConfig& cfg = points_[i];
    const ReplayRunner& r = runner_;
    if (m == kRecord)
      return {i,
              [&r, &cfg] {
                std::vector<std::uint8_t> trace;
                std::string out = report_frame([&] { return r.record(cfg, &trace); });
                return out.append(trace.begin(), trace.end()); // (none: unreplayable)
              },
              m};
    if (m == kReplay)
      return {i,
              [&r, &cfg, &trace = traces_.at(keys_[i])] {
                return report_frame([&] {
                  std::optional<nlohmann::json> rep = r.replay(cfg, trace);
                  return rep ? std::move(*rep) : nlohmann::json{{kDiverged, true}};
                });
              },
              m};
    return {i, [&r, &cfg] { return report_frame([&] { return r.record(cfg, nullptr); }); }, m};
  }

  const std::vector<RunConfig>& points_;
  const ReplayRunner& runner_;
  TraceStore& traces_;
  std::vector<std::string> keys_;
  std::deque<std::pair<std::size_t, bool>> pending_; // the point, and whether to run it in full
  std::set<std::string> recording_, unreplayable_;
};

} // namespace

std::vector<nlohmann::json>
run_batch_replaying(const std::vector<RunConfig>& points, int jobs, const ReplayRunner& runner,
                    TraceStore& traces, const std::function<void(const BatchProgress&)>& progress,
                    ReplayCounts* counts) {
  PackedReports reports(points.size());
  BatchProgress pr;
  pr.total = points.size();
  ReplaySchedule schedule(points, runner, traces);
  std::size_t running = 0;
  const NextJob next = [&]() -> std::optional<Job> {
    auto job = schedule.next(running == 0);
    if (job) ++running;
    return job;
  };
  run_jobs(jobs, next, [&](Child& c) {
    --running;
    nlohmann::json rep;
    if (!schedule.done(c, rep)) return;
    if (rep.value("status", "error") == "error") ++pr.failed;
    reports.set(c.job.index, rep);
    ++pr.done;
    if (progress) progress(pr);
  });
  if (counts) *counts = schedule.counts;
  return reports.unpack();
}

} // namespace zc
