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

// A value's tolerance class, from its place in the reduced report: times (phases, *_s, the load
// imbalance, a ratio of times), bytes (*bytes*), counts (every other number), text (anything else:
// equal or not).
enum class QuantityKind { time, count, bytes, text };
QuantityKind quantity_kind(const std::string& path, const nlohmann::json& value);
const char* kind_name(QuantityKind kind);

// Two numbers are equal when |a - b| <= max(atol, rtol * max(|a|, |b|)), rtol that of their class
// (atol in the quantity's own unit; counts and bytes are integers, so an atol below 1 leaves them
// exact).
struct RegressTolerance {
  double rtol_time = 0, rtol_count = 0, rtol_bytes = 0, atol = 0;
  static RegressTolerance uniform(double rtol) { return {rtol, rtol, rtol, 0}; }
  double rtol(QuantityKind kind) const;
  std::string text(QuantityKind kind) const; // "rtol 1e-09, atol 0" ("exact" for text)
};

struct RegressDiff {
  std::string run, quantity, before, after;
  double rel = 0; // relative change of a number (0 for text)
  QuantityKind kind = QuantityKind::text;
  std::string tolerance; // the one it exceeded (RegressTolerance::text)
};
// Every difference between two reduced reports, one per leaf value (a missing run on either side
// is one too, and a run whose status changed is one row: its status and error); a report's
// "provenance" is not compared. Numbers within the tolerance of their class are equal (0: bit for
// bit).
std::vector<RegressDiff> compare_reduced(const std::map<std::string, nlohmann::json>& before,
                                         const std::map<std::string, nlohmann::json>& after,
                                         const RegressTolerance& tolerance);
inline std::vector<RegressDiff> compare_reduced(const std::map<std::string, nlohmann::json>& before,
                                                const std::map<std::string, nlohmann::json>& after,
                                                double rtol = 0) {
  return compare_reduced(before, after, RegressTolerance::uniform(rtol));
}

// The runs whose status is "error", with their reasons ("name: reason").
std::vector<std::string> failed_runs(const std::map<std::string, nlohmann::json>& reduced);

// A directory of <name>.json reduced reports; each written with the provenance of a committed
// file (repro/provenance.hpp), read with its provenance if it has one.
std::map<std::string, nlohmann::json> read_report_dir(const std::string& dir);
void write_report_dir(const std::map<std::string, nlohmann::json>& reps, const std::string& dir);

// The provenance of a directory's reports (the first file's that has one; null when none has),
// and UsageError (one line naming `flag`, the directory and a file) when a report's schema is not
// this zcube's, unless `allow_other_schema`. A report without provenance is schema 0.
nlohmann::json check_report_schema(const std::map<std::string, nlohmann::json>& reps,
                                   const std::string& flag, const std::string& dir,
                                   bool allow_other_schema);

} // namespace zc
