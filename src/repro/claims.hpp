#pragma once
// The papers' qualitative statements that tests/repro/test_paper_claims.cpp checks (enabled or
// disabled), with the probability, under the uncertainty model's bands (docs/uncertainty.md), that
// the model reproduces each: `zcube reproduce` writes them to results/claims.csv.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "repro/reproduce.hpp"

namespace zc {

// One draw's figures of the runs a claim reads, by point key: the nominal run (draw -1) or a draw.
class ClaimDraw {
public:
  ClaimDraw(const Reports& reps, int draw) : reps_(reps), draw_(draw) {}
  // The run's time (its timed region, else the whole run); NaN where the draw failed.
  double time(const std::string& key) const;
  // The critical node's time in a phase; NaN where the draw failed.
  double phase(const std::string& key, const std::string& name) const;
  // Whether the run finished (not out of node memory) under this draw.
  bool finished(const std::string& key) const;
  // A figure that does not depend on the machine (a byte count): the nominal run's.
  const nlohmann::json& report(const std::string& key) const { return reps_.at(key); }

private:
  const Reports& reps_;
  int draw_;
};

struct Claim {
  std::string test;      // the PaperClaims test that checks it (DISABLED_ prefix when disabled)
  std::string paper;     // the source
  std::string statement; // the paper's words, short
  // Whether the statement holds under one draw; nullopt-like NaN handling: false on a failed draw.
  std::function<bool(const ClaimDraw&)> holds;
};

// The claims and the runs they read (points of the "claims" plan).
const std::vector<Claim>& paper_claims();
PaperPlan claims_plan(const ReproduceOptions& o);

// The share of the draws (of those the runs' bands have) under which the claim holds.
double claim_probability(const Claim& c, const Reports& reps, int draws);

} // namespace zc
