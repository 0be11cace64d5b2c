#pragma once
// Many simulations at once: SimGrid runs one engine per process, so each point is a forked child
// (a fresh engine) and up to `jobs` of them run together. A point that fails, throws or dies
// (signal, out of host memory) comes back as a report with "status": "error" and a reason; the
// other points are not affected.
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run/config.hpp"

namespace zc {

struct BatchProgress {
  std::size_t done = 0, total = 0, failed = 0;
};

// How a point runs in its child process: its report (the backend that simulates it, and what the
// caller attaches, are the caller's: sim/ provides the simulation, repro/ the paper figures).
using PointRunner = std::function<nlohmann::json(const RunConfig&)>;

// Reports in the order of `points`. `progress` (may be empty) is called in the parent after each
// point completes.
std::vector<nlohmann::json>
run_batch(const std::vector<RunConfig>& points, int jobs, const PointRunner& run_point,
          const std::function<void(const BatchProgress&)>& progress = {});

// Record and replay (docs/simulator.md): points whose node programs make the same calls (the
// same `key`) are run once in full, recording their calls, and the others replay the recording.
struct ReplayRunner {
  // The points that make the same calls share a key; "" for a point always run in full.
  std::function<std::string(const RunConfig&)> key;
  // A full run; fills `trace` with its recorded calls when it can be replayed.
  std::function<nlohmann::json(const RunConfig&, std::vector<std::uint8_t>* trace)> record;
  // A replay of `trace`; nullopt when it diverged (the point then runs in full).
  std::function<std::optional<nlohmann::json>(const RunConfig&, const std::vector<std::uint8_t>&)>
      replay;
};
// How the points of such batches ran.
struct ReplayCounts {
  std::size_t full = 0, recorded = 0, replayed = 0, diverged = 0;
};
// Traces by key, kept by the caller across batches (the calibration's steps replay the first's).
using TraceStore = std::map<std::string, std::vector<std::uint8_t>>;

// run_batch with record and replay: the first point of each key records (the others of that key
// wait for it), the rest replay; a replay that diverges is run again in full.
std::vector<nlohmann::json> run_batch_replaying(
    const std::vector<RunConfig>& points, int jobs, const ReplayRunner& runner, TraceStore& traces,
    const std::function<void(const BatchProgress&)>& progress = {}, ReplayCounts* counts = nullptr);

// The host's core count (at least 1): the default of --jobs.
int default_jobs();

} // namespace zc
