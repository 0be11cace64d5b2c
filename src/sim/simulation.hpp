#pragma once
// One simulation: a platform (built-in machine or XML file) with what-if overrides, an algorithm,
// a scene; runs the node (and host) actors on SimGrid and returns the report (docs/user-guide.md,
// "One run"). SimGrid allows one engine per process: run_simulation may be called once per process
// (run_simulation_isolated forks for callers that need more, such as tests and sweeps).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run/config.hpp"

namespace zc {

struct PlatformModel;
// `model`, when given, receives the machine the run was priced on (what-ifs and draw applied).
RunResult run_simulation(const RunConfig& cfg, const Scene* preloaded = nullptr,
                         PlatformModel* model = nullptr);

// Runs in a forked child (fresh SimGrid engine) and returns its report; images are not returned.
nlohmann::json run_simulation_isolated(const RunConfig& cfg);

} // namespace zc
