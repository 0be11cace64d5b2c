// The compositing study's plan (results/compositing/): its committed tables are a real run, --full
// covers every Kurc scene while the quick grid stays one scene, and a run without --full leaves
// the committed --full tables alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "csv.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"
#include "repro/table.hpp"
#include "source_root.hpp"

using namespace zc;

namespace {
using test::kRoot;
}

TEST(ReproduceCompositing, CommittedTablesAreCurrentAtEightNodes) {
  ReproduceOptions o;
  o.root = kRoot;
  const PaperPlan p = compositing_plan(o);
  RunConfig cfg;
  for (const auto& pt : p.points)
    if (pt.key == "2pot/ipsc2/cube/400/8") cfg = pt.cfg;
  ASSERT_EQ(cfg.nodes, 8);
  const auto r = simulate_batch({cfg}, 1, {})[0];
  ASSERT_EQ(r["status"], "ok") << r.dump().substr(0, 400);
  int checked = 0;
  for (const auto& row : test::read_csv(kRoot + "/results/compositing/merging.csv")) {
    if (row.at("scene") != "2pot" || row.at("machine") != "ipsc2" || row.at("topology") != "cube" ||
        row.at("width") != "400" || row.at("nodes") != "8")
      continue;
    for (const auto& ph : r["phases"])
      if (ph["name"] == row.at("algorithm")) {
        EXPECT_EQ(fixed(ph["max_s"].get<double>() * 1e3, 3), row.at("merging_ms"))
            << row.at("algorithm");
        ++checked;
      }
  }
  EXPECT_GE(checked, 5);
}

// The committed tables hold every scene of results/kurc (Table 1's six); the quick grid (part of
// the default `zcube reproduce`) stays 22 points of 2 POT.
TEST(ReproduceCompositing, FullCoversEveryKurcSceneQuickKeepsOne) {
  std::set<std::string> kurc, committed, planned;
  for (const auto& row : test::read_csv(kRoot + "/results/kurc/table1.csv"))
    kurc.insert(row.at("scene"));
  for (const auto& row : test::read_csv(kRoot + "/results/compositing/best.csv"))
    committed.insert(row.at("scene"));
  ReproduceOptions o;
  o.root = kRoot;
  o.full = true;
  const PaperPlan full = compositing_plan(o);
  for (const auto& pt : full.points)
    planned.insert(pt.key.substr(0, pt.key.find('/')));
  EXPECT_EQ(kurc.size(), 6u);
  EXPECT_EQ(planned, kurc);
  EXPECT_EQ(committed, kurc);
  o.full = false;
  const PaperPlan quick = compositing_plan(o);
  EXPECT_EQ(quick.points.size(), 22u);
  for (const auto& pt : quick.points)
    EXPECT_TRUE(pt.key.starts_with("2pot/")) << pt.key;
}

TEST(ReproduceCompositing, AQuickRunLeavesTheFullTables) {
  const auto dir = std::filesystem::temp_directory_path() / "zcube-compositing-plan";
  std::filesystem::create_directories(dir / "compositing");
  std::ofstream(dir / "compositing/merging.csv")
      << "machine,topology,size,scene,nodes,contender,merging_ms\nipsc2,cube,400,2pot,1024,"
         "binary-swap,49\n";
  ReproduceOptions o;
  o.root = kRoot;
  o.out = dir.string();
  std::string note;
  EXPECT_EQ(plan_directory(o, compositing_plan(o), &note), o.out + "/compositing-quick");
  o.full = true;
  EXPECT_EQ(plan_directory(o, compositing_plan(o), &note), o.out + "/compositing");
  std::filesystem::remove_all(dir);
}
