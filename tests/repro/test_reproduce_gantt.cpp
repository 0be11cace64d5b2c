// zcube reproduce's space-time diagrams: each paper draws its representative runs, and
// every chart names a point its plan simulates.
#include <algorithm>

#include <gtest/gtest.h>

#include "repro/reproduce.hpp"

using namespace zc;

TEST(ReproduceGantt, EveryPaperChartsPointsOfItsOwnPlan) {
  ReproduceOptions o;
  o.root = ZCUBE_SOURCE_DIR;
  for (const auto& plan : {kurc_plan(o), charles_plan(o), blazek_plan(o)}) {
    EXPECT_EQ(plan.gantt.size(), 2u) << plan.name; // two runs side by side
    for (const auto& g : plan.gantt) {
      const bool found = std::any_of(plan.points.begin(), plan.points.end(),
                                     [&](const ReproPoint& p) { return p.key == g.key; });
      EXPECT_TRUE(found) << plan.name << ": " << g.key;
      EXPECT_TRUE(g.file.ends_with(".png")) << g.file;
    }
    EXPECT_NE(gantt_markdown(plan.gantt).find(plan.gantt.front().file), std::string::npos);
  }
}
