#pragma once
// Many simulations at once: SimGrid runs one engine per process, so each point is a forked child
// (a fresh engine) and up to `jobs` of them run together. A point that fails, throws or dies
// (signal, out of host memory) comes back as a report with "status": "error" and a reason; the
// other points are not affected.
#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "run/config.hpp"

namespace zc {

struct BatchProgress {
  std::size_t done = 0, total = 0, failed = 0;
};

// How a point runs in its child process: its report (the backend that simulates it, and what the
// caller attaches, are the caller's: sim/ provides the simulation, repro/ the paper figures).
using PointRunner = std::function<nlohmann::json(const SimConfig&)>;

// Reports in the order of `points`. `progress` (may be empty) is called in the parent after each
// point completes.
std::vector<nlohmann::json>
run_batch(const std::vector<SimConfig>& points, int jobs, const PointRunner& run_point,
          const std::function<void(const BatchProgress&)>& progress = {});

// The host's core count (at least 1): the default of --jobs.
int default_jobs();

} // namespace zc
