#pragma once
// What `zcube regress` found, as people read it (a Markdown table), as JSON and as JUnit XML for
// a CI server (one test case per run).
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "repro/regress.hpp"

namespace zc {

// One side of a comparison: its name (a directory, or "now" for this build's runs) and where its
// reports came from (provenance, null when they carry none).
struct RegressSide {
  std::string name;
  nlohmann::json provenance;
};

struct RegressOutcome {
  RegressSide before, after;
  std::vector<std::string> runs;             // every run of either side, sorted
  std::vector<RegressDiff> diffs;            // compare_reduced
  std::map<std::string, std::string> failed; // run -> reason, for the runs that failed now
  RegressTolerance tolerance;
  bool identical() const { return diffs.empty() && failed.empty(); }
};

// "regress: tests/golden: zcube 0.9.0, SimGrid 3.32.0, schema 1" for each side.
std::string regress_sides_text(const RegressOutcome& o);
// The differences as a Markdown table and a last line with their count (or "identical").
std::string regress_text(const RegressOutcome& o);
nlohmann::json regress_json(const RegressOutcome& o);
// <testsuites><testsuite name="zcube regress"> with a <testcase> per run; a run that differs has a
// <failure> whose message names each quantity, both values and the tolerance it exceeded.
std::string regress_junit(const RegressOutcome& o);

} // namespace zc
