#pragma once
// The progress line of long batches on stderr: "label: 12/40 done, 8.1 s elapsed, about 19 s
// left". Rewritten in place on a terminal; otherwise one line per tenth of the work or per 5 s,
// whichever comes first (logs of CI stay readable, and a long batch is never silent for long
// between completed points).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <string>

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

inline std::function<void(const BatchProgress&)> progress_printer(const std::string& label) {
  using Clock = std::chrono::steady_clock;
  const bool tty = isatty(2);
  const auto start = Clock::now();
  return
      [label, tty, start, last = std::size_t(0), printed = start](const BatchProgress& p) mutable {
        const auto now = Clock::now();
        const double elapsed = std::chrono::duration<double>(now - start).count();
        std::string text = label + ": " + std::to_string(p.done) + "/" + std::to_string(p.total) +
                           " done" + (p.failed ? ", " + std::to_string(p.failed) + " failed" : "") +
                           ", " + human_seconds(elapsed) + " elapsed";
        if (p.done > 0 && p.done < p.total)
          text += ", about " + human_seconds(elapsed / double(p.done) * double(p.total - p.done)) +
                  " left";
        const std::size_t tenth = p.done * 10 / std::max<std::size_t>(p.total, 1);
        if (tty) {
          std::cerr << "\r" << text << "\033[K" << (p.done == p.total ? "\n" : "") << std::flush;
        } else if (p.done == p.total || tenth > last ||
                   std::chrono::duration<double>(now - printed).count() >= 5) {
          last = tenth;
          printed = now;
          std::cerr << text << "\n";
        }
      };
}

} // namespace zc
