// The compositing study's plan (results/compositing/): its committed tables are a real run, and a
// run without --full leaves the committed --full tables alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "csv.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"
#include "repro/table.hpp"

using namespace zc;

namespace {
const std::string kRoot = ZCUBE_SOURCE_DIR;
}

TEST(ReproduceCompositing, CommittedTablesAreCurrentAtEightNodes) {
  ReproduceOptions o;
  o.root = kRoot;
  const PaperPlan p = compositing_plan(o);
  SimConfig cfg;
  for (const auto& pt : p.points)
    if (pt.key == "ipsc2/cube/400/8") cfg = pt.cfg;
  ASSERT_EQ(cfg.nodes, 8);
  const auto r = simulate_batch({cfg}, 1, {})[0];
  ASSERT_EQ(r["status"], "ok") << r.dump().substr(0, 400);
  int checked = 0;
  for (const auto& row : test::read_csv(kRoot + "/results/compositing/merging.csv")) {
    if (row.at("machine") != "ipsc2" || row.at("topology") != "cube" || row.at("size") != "400" ||
        row.at("nodes") != "8")
      continue;
    for (const auto& ph : r["phases"])
      if (ph["name"] == row.at("contender")) {
        EXPECT_EQ(fixed(ph["max_s"].get<double>() * 1e3, 3), row.at("merging_ms"))
            << row.at("contender");
        ++checked;
      }
  }
  EXPECT_GE(checked, 5);
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
