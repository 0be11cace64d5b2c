// machine/calibrated_costs: the cost groups of the counters and each machine's calibrated table
// within its plausible range.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "csv.hpp"
#include "machine/cpu_model.hpp"
#include "machine/machine.hpp"
#include "repro/paper_figures.hpp"
#include "repro/regress.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"
#include "repro/sweep.hpp"
#include "util/error.hpp"
#include "util/nnls.hpp"

using namespace zc;

TEST(CostGroups, EveryCounterFieldIsInExactlyOneGroup) {
  CostTable t;
  std::multiset<std::string> seen;
  for (const auto& g : cost_groups())
    for (const auto& f : g.fields)
      seen.insert("cost_" + f);
  for (auto& [id, v] : t.fields())
    EXPECT_EQ(seen.count(id), 1u) << id;
  EXPECT_EQ(seen.size(), t.fields().size());
}

TEST(CostGroups, ScalingMultipliesOnlyTheGroupsFields) {
  const CostTable p = prior_i386_costs();
  std::vector<double> k(cost_groups().size(), 1.0);
  k[4] = 3.0; // merge
  CostTable s = scale_groups(p, k);
  EXPECT_DOUBLE_EQ(s.merge_ops, 3 * p.merge_ops);
  EXPECT_DOUBLE_EQ(s.spans, p.spans);
  EXPECT_EQ(cost_groups()[4].name, "merge");
}

TEST(CalibratedTables, EachMachineUsesItsOwnCpusPhysicalTableWithinThePlausibleRange) {
  const auto k = calibrated_group_scale();
  ASSERT_EQ(k.size(), cost_groups().size());
  for (double v : k) {
    EXPECT_GE(v, plausible_low());
    EXPECT_LE(v, plausible_high());
  }
  EXPECT_EQ(machine_spec("ipsc2").cpu, "i80386");
  EXPECT_EQ(machine_spec("ipsc860").cpu, "i860xr");
  EXPECT_EQ(machine_spec("volvox").cpu, "i860xr");
  const CostTable expect386 = cpu_seconds(cpu_model("i80386"), k);
  const CostTable expect860 = cpu_seconds(cpu_model("i860xr"), k);
  EXPECT_EQ(machine_spec("ipsc2").cost.pixels_written, expect386.pixels_written);
  EXPECT_EQ(machine_spec("ipsc860").cost.vertices_transformed, expect860.vertices_transformed);
  // The i860 is faster at every operation that costs anything, but not by one ratio.
  CostTable a = expect386, b = expect860;
  const auto fa = a.fields(), fb = b.fields();
  double lo = 1e300, hi = 0;
  for (std::size_t i = 0; i < fa.size(); ++i) {
    if (*fa[i].second == 0) continue;
    const double r = *fa[i].second / *fb[i].second;
    EXPECT_GT(r, 1) << fa[i].first;
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  EXPECT_GT(hi / lo, 1.5);
}
