#pragma once
// The progress line of long batches on stderr: rewritten in place on a terminal, one line per
// tenth of the work otherwise (logs of CI stay readable).
#include <unistd.h>

#include <functional>
#include <iostream>
#include <string>

#include "run/batch.hpp"

namespace zc {

inline std::function<void(const BatchProgress&)> progress_printer(const std::string& label) {
  const bool tty = isatty(2);
  return [label, tty, last = std::size_t(0)](const BatchProgress& p) mutable {
    const std::string text = label + ": " + std::to_string(p.done) + "/" + std::to_string(p.total) +
                             " done" +
                             (p.failed ? ", " + std::to_string(p.failed) + " failed" : "");
    if (tty) {
      std::cerr << "\r" << text << (p.done == p.total ? "\n" : "") << std::flush;
    } else if (p.done == p.total || p.done * 10 / std::max<std::size_t>(p.total, 1) > last) {
      last = p.done * 10 / std::max<std::size_t>(p.total, 1);
      std::cerr << text << "\n";
    }
  };
}

} // namespace zc
