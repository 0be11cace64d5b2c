#pragma once
// The progress line of long batches on stderr: "label: 12/40 done, 8.1 s elapsed, about 19 s
// left". Rewritten in place on a terminal; otherwise one line per tenth of the work or per 5 s,
// whichever comes first. A heartbeat thread repeats the line every 10 s while no point completes,
// so a long job is never silent for longer (a single point may take minutes). Lines go out with
// write(2), never through stdio: the batch forks its simulations while the heartbeat runs, and a
// child must not inherit a stdio lock the heartbeat held.
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "run/batch.hpp"

namespace zc {

// "8.1 s", "3 min 05 s": a duration as a person reads it.
inline std::string human_seconds(double s) {
  char buf[48];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.1f s", s);
  else
    std::snprintf(buf, sizeof buf, "%d min %02d s", int(s) / 60, int(s) % 60);
  return buf;
}

class ProgressLine {
public:
  using Clock = std::chrono::steady_clock;

  ProgressLine(std::string label, std::size_t total)
      : label_(std::move(label)), tty_(isatty(2)), start_(Clock::now()), printed_(start_) {
    state_.total = total;
    heartbeat_ = std::thread([this] { beat(); });
  }
  ~ProgressLine() {
    {
      std::lock_guard<std::mutex> l(m_);
      stop_ = true;
    }
    cv_.notify_all();
    heartbeat_.join();
  }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void update(const BatchProgress& p) {
    std::lock_guard<std::mutex> l(m_);
    state_ = p;
    const std::size_t tenth = p.done * 10 / std::max<std::size_t>(p.total, 1);
    const double quiet = std::chrono::duration<double>(Clock::now() - printed_).count();
    if (tty_ || p.done == p.total || tenth > tenth_ || quiet >= 5) {
      tenth_ = tenth;
      emit(p.done == p.total);
    }
  }

private:
  // Every 10 s without a line, the line again (elapsed and ETA move on).
  void beat() {
    std::unique_lock<std::mutex> l(m_);
    while (!stop_) {
      cv_.wait_for(l, std::chrono::seconds(1));
      const bool finished = state_.total > 0 && state_.done == state_.total;
      if (!stop_ && !finished &&
          std::chrono::duration<double>(Clock::now() - printed_).count() >= 10)
        emit(false);
    }
  }

  void emit(bool last) { // m_ held
    printed_ = Clock::now();
    const double elapsed = std::chrono::duration<double>(printed_ - start_).count();
    const BatchProgress& p = state_;
    std::string text = label_ + ": " + std::to_string(p.done) + "/" +
                       (p.total ? std::to_string(p.total) : std::string("?")) + " done" +
                       (p.failed ? ", " + std::to_string(p.failed) + " failed" : "") + ", " +
                       human_seconds(elapsed) + " elapsed";
    if (p.done > 0 && p.done < p.total)
      text +=
          ", about " + human_seconds(elapsed / double(p.done) * double(p.total - p.done)) + " left";
    text = tty_ ? "\r" + text + "\033[K" + (last ? "\n" : "") : text + "\n";
    (void)!::write(2, text.data(), text.size());
  }

  std::string label_;
  bool tty_;
  Clock::time_point start_, printed_;
  BatchProgress state_;
  std::size_t tenth_ = 0;
  bool stop_ = false;
  std::mutex m_;
  std::condition_variable cv_;
  std::thread heartbeat_;
};

// The callback of a batch; its heartbeat stops when the last copy of the callback is destroyed.
// `total`: the number of points, when known before the first one completes.
inline std::function<void(const BatchProgress&)> progress_printer(const std::string& label,
                                                                  std::size_t total = 0) {
  if (std::getenv("ZCUBE_QUIET")) return {}; // zcube -q: errors only
  auto line = std::make_shared<ProgressLine>(label, total);
  return [line](const BatchProgress& p) { line->update(p); };
}

} // namespace zc
