#include "mpi/probe_solve.hpp"

#include <algorithm>
#include <stdexcept>

#include "mpi/probe_groups.hpp"
#include "util/nnls.hpp"

namespace zc::cpu_probe {

namespace {

// One block's loops, solved for the block's groups: each loop's time less its groups measured
// before (`k` where `known`), divided among the block's own groups (non-negative least squares on
// relative errors). With `alone` (the multipliers rank 0 found timing the loops alone), a block of
// several groups is solved for one common slowdown s over the alone split (k = s x alone): timed
// at once, the ranks' shared memory system makes the z-buffer's split unsteady from one probe to
// the next while its sum on the probe's loops stays steady. Returns s (1 when
// free).
double solve_block(std::size_t b, const std::vector<Loop>& loops,
                   const std::vector<std::vector<double>>& A, const std::vector<double>& alone,
                   std::vector<double>& k, std::vector<bool>& known) {
  const auto& gs = loop_blocks()[b].groups;
  double alone_sum = 0;
  for (std::size_t g : gs)
    alone_sum += alone.empty() ? 0.0 : alone[g];
  const bool common = gs.size() > 1 && alone_sum > 0;
  Matrix M;
  std::vector<double> r;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (loops[i].block != b) continue;
    double rest = loops[i].seconds;
    std::vector<double> row;
    double at_alone = 0; // the block's groups priced at the alone multipliers
    for (std::size_t g = 0; g < kProbeGroups; ++g) {
      const bool mine = std::find(gs.begin(), gs.end(), g) != gs.end();
      if (known[g])
        rest -= k[g] * A[i][g];
      else if (mine && common)
        at_alone += alone[g] * A[i][g];
      else if (mine)
        row.push_back(A[i][g] / loops[i].seconds);
      else if (A[i][g] > 0)
        throw std::logic_error("probe loop '" + loops[i].name + "' runs group " +
                               probe_groups()[g].name + " before it is measured");
    }
    if (common) row.push_back(at_alone / loops[i].seconds);
    M.push_back(row);
    r.push_back(rest / loops[i].seconds);
  }
  if (M.empty())
    throw std::logic_error(std::string("probe block without loop: ") + loop_blocks()[b].name);
  const std::vector<double> x = nnls(M, r);
  // A core that shares the memory system and the last-level cache with busy ones is no faster
  // than alone: at once, a group's cost is floored at its alone cost (the fit's slowdown, returned,
  // may come out below 1 from the noise of the subtraction chain alone, even when the loops run
  // as fast at once as alone).
  const bool floored = !alone.empty();
  for (std::size_t j = 0; j < gs.size(); ++j) {
    const double fitted = common ? x[0] * alone[gs[j]] : x[j];
    k[gs[j]] = floored ? std::max(fitted, alone[gs[j]]) : fitted;
    known[gs[j]] = true;
  }
  return common ? x[0] : 1.0;
}

} // namespace

// Solves the blocks in order (solve_block). Returns one multiplier a group on the prior table and
// writes every loop's fitted prediction into `log`.
std::vector<double> solve(const std::vector<Loop>& loops, const std::vector<double>& alone,
                          nlohmann::json& log) {
  const CostTable prior = probe_prior();
  std::vector<double> k(kProbeGroups, 0.0);
  std::vector<bool> known(kProbeGroups, false);
  std::vector<std::vector<double>> A;
  for (const Loop& l : loops)
    A.push_back(group_seconds(prior, probe_groups(), l.c));
  nlohmann::json slowdown = nlohmann::json::object();
  for (std::size_t b = 0; b < loop_blocks().size(); ++b) {
    const double s = solve_block(b, loops, A, alone, k, known);
    if (loop_blocks()[b].groups.size() > 1 && !alone.empty()) slowdown[loop_blocks()[b].name] = s;
  }
  nlohmann::json rows = nlohmann::json::array(), groups = nlohmann::json::array(),
                 mult = nlohmann::json::object(), per_op = nlohmann::json::object();
  for (std::size_t i = 0; i < loops.size(); ++i) {
    double pred = 0;
    nlohmann::json by_group = nlohmann::json::object();
    for (std::size_t g = 0; g < kProbeGroups; ++g) {
      pred += k[g] * A[i][g];
      if (A[i][g] > 0) by_group[probe_groups()[g].name] = A[i][g];
    }
    rows.push_back({{"loop", loops[i].name},
                    {"block", loop_blocks()[loops[i].block].name},
                    {"seconds", loops[i].seconds},
                    {"calls", loops[i].calls},
                    {"counters", loops[i].c},
                    {"prior_s", by_group},
                    {"predicted_s", pred}});
  }
  for (std::size_t g = 0; g < kProbeGroups; ++g) {
    groups.push_back({{"group", probe_groups()[g].name}, {"fields", probe_groups()[g].fields}});
    mult[probe_groups()[g].name] = k[g];
  }
  CostTable prior_t = prior;
  for (auto& [id, v] : prior_t.fields())
    per_op[id.substr(5)] = *v;
  // The loops (each its counters, time, the prior's seconds a group and the fitted prediction),
  // the groups, the prior table (seconds an operation on the 80386) and each group's multiplier on
  // it: what scripts/probe_instructions.py re-solves on instruction counts.
  log = {{"loops", rows},
         {"groups", groups},
         {"prior_i386_s", per_op},
         {"multipliers", mult},
         {"slowdown_over_alone", slowdown}};
  return k;
}

} // namespace zc::cpu_probe
