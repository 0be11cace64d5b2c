#pragma once
// A prediction with its band and its sensitivities (docs/uncertainty.md). The run is simulated
// once, recording its calls; each draw of the uncertainty model (machine/uncertainty.hpp) then
// prices those calls again: retimed in this process (sim/retime.hpp) where the retimer reproduces
// the simulator, else replayed by full simulations in child processes. The report gains a "bands"
// section (p05, p50, p95 of the virtual time, the timed region and every phase, and every draw's
// values, so that a study can pair its points draw by draw) and, when asked, a "sensitivity"
// section (the elasticity d ln T / d ln theta of every model parameter).
#include <cstdint>

#include "run/config.hpp"

namespace zc {

struct BandsRequest {
  int draws = 0; // 0: no band
  std::uint64_t seed = 1;
  bool sensitivity = false;
  double step = 0.01; // the sensitivity's relative step (central differences in log space)
};

struct CallTrace;
struct PlatformModel;
// Marks the bands and sensitivities `req` asks for (those the report has not got) unavailable,
// and why.
void mark_unavailable(Report& report, const BandsRequest& req, const std::string& why);
// Adds the bands and sensitivities of `req` to `report`, the report of the run that recorded
// `trace` on `pm` (its machine after what-ifs), by retiming; where it cannot (a machine the
// retimer does not cover, or a retimer that disagrees with the run), marks them unavailable and
// returns why ("" when it did).
std::string add_bands(Report& report, const CallTrace& trace, const PlatformModel& pm,
                      const RunConfig& cfg, const BandsRequest& req);

// Like run_simulation, once per process; the draws that need a simulation of their own fork.
RunResult run_with_bands(const RunConfig& cfg, const BandsRequest& req,
                         const Scene* preloaded = nullptr);

} // namespace zc
