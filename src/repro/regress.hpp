#pragma once
// Regression of simulated timings: a standard set of runs (tests/golden/runs.json) whose reduced
// reports (virtual times, phase times, image hashes, message counts, operation counts) are kept as
// golden files; any change of one of them is a difference. Used by the test suite and by users
// comparing two versions or two platform files (`zcube regress`).
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace zc {

struct RegressRun {
  std::string name;
  std::map<std::string, std::string> flags; // zcube run flags (sim/run_flags.hpp)
};

// Reads a runs file ({"runs": [{"name": ..., flag: value, ...}]}); InputError on a bad file.
std::vector<RegressRun> read_regress_runs(const std::string& path);

// Runs them (each in its own process, `jobs` at a time) and returns the reduced reports by name.
// Scene paths are relative to `root`; `set` overrides flags of every run. Before anything runs, a
// `set` key that is not a run flag, or a run the overrides make invalid, is a UsageError (one
// line naming the run and the flag).
std::map<std::string, nlohmann::json> run_regress(const std::vector<RegressRun>& runs,
                                                  const std::string& root, int jobs,
                                                  const std::map<std::string, std::string>& set);

// The part of a report that must not change: status, virtual time, phases, image hash, message and
// byte counts, operation counts, memory peak.
nlohmann::json reduce_report(const nlohmann::json& report);

struct RegressDiff {
  std::string run, quantity, before, after;
  double rel = 0; // relative change of a number (0 for text)
};
// Every difference between two reduced reports, one per leaf value (a missing run on either side
// is one too, and a run whose status changed is one row: its status and error). Numbers whose
// relative difference is at most rtol are equal (rtol = 0: bit for bit).
std::vector<RegressDiff> compare_reduced(const std::map<std::string, nlohmann::json>& before,
                                         const std::map<std::string, nlohmann::json>& after,
                                         double rtol = 0);

// The runs whose status is "error", with their reasons ("name: reason").
std::vector<std::string> failed_runs(const std::map<std::string, nlohmann::json>& reduced);

// A directory of <name>.json reduced reports.
std::map<std::string, nlohmann::json> read_report_dir(const std::string& dir);
void write_report_dir(const std::map<std::string, nlohmann::json>& reps, const std::string& dir);

} // namespace zc
