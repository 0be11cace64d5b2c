#pragma once
// Record and replay on the simulator (docs/simulator.md, "Record and replay"): a run recorded
// once (run/call_trace.hpp) is replayed under other CPU costs, another network, fidelity or node
// memory by the same SimContext and SimComm that run the algorithms, executing the recorded calls
// with messages counted and charged at the recorded sizes but no bytes behind them; the report is
// the one a full run would write. A replay that the trace cannot reproduce (a receive from any
// source that gets another source, a node out of memory with sends in flight, another node count
// or topology) is abandoned: the caller runs the point in full.
#include <memory>
#include <optional>
#include <string>

#include "run/call_trace.hpp"
#include "run/config.hpp"

namespace zc {

struct PlatformModel;

// A full run (run_simulation) that records its calls into `trace`; `trace` is reset when the run
// cannot be replayed (it failed, or a node read the clock).
// `model`, when given, receives the machine the run was priced on.
RunResult record_simulation(const RunConfig& cfg, const Scene* preloaded,
                            std::shared_ptr<CallTrace>& trace, PlatformModel* model = nullptr);

// The result of `cfg` by replaying `trace` (recorded from a run of the same algorithm, options,
// scene, size, frames, node count and topology); nullopt, and `why`, when the replay diverged.
// Like run_simulation, once per process. The images are not made: the image section is the
// recorded run's.
std::optional<RunResult> replay_simulation(const RunConfig& cfg, const Scene* preloaded,
                                           std::shared_ptr<const CallTrace> trace,
                                           std::string* why = nullptr,
                                           PlatformModel* model = nullptr);

} // namespace zc
