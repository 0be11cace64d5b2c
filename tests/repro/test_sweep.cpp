// repro/sweep: expansion of the flags, baselines and speed-ups against the matching reference.
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
#include "source_root.hpp"
#include "util/error.hpp"
#include "util/nnls.hpp"

using namespace zc;

namespace {

using test::kRoot;

using test::read_csv;

} // namespace

// A platform file states its own node count: its baseline runs on it without --nodes 1 (which the
// file would refuse), sequential rendering on node 0 alone.
TEST(Sweep, ABaselineOnAPlatformFileTakesTheFilesNodes) {
  const std::string xml = kRoot + "/platforms/volvox-ring-8.xml";
  const std::vector<SweepAxis> axes = {{"machine", {xml}}, {"algorithm", {"elastic"}}};
  auto pts = expand_sweep(axes, kRoot + "/scenes/teapot.json");
  add_baselines(axes, pts, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 2u);
  ASSERT_TRUE(is_baseline(pts[1]));
  ASSERT_TRUE(pts[1].config.has_value()) << pts[1].error;
  EXPECT_EQ(pts[1].config->nodes, 0); // the file's
  EXPECT_EQ(pts[1].config->algorithm, "sequential");
  const std::vector<nlohmann::json> reps = {
      {{"status", "ok"}, {"nodes", 8}, {"virtual_time_s", 2.0}},
      {{"status", "ok"}, {"nodes", 8}, {"virtual_time_s", 8.0}}};
  auto rows = sweep_rows(axes, pts, reps);
  ASSERT_TRUE(add_speedups(pts, reps, rows));
  EXPECT_DOUBLE_EQ(rows[0]["efficiency"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(rows[1]["efficiency"].get<double>(), 1.0); // one node works
}

TEST(Sweep, ExpandsTheCartesianProductFirstAxisSlowest) {
  const auto pts = expand_sweep({{"nodes", {"1", "2", "3"}}, {"latency", {"10us", "1ms"}}},
                                kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 6u);
  EXPECT_EQ(pts[0].values.at("nodes"), "1");
  EXPECT_EQ(pts[1].values.at("latency"), "1ms");
  EXPECT_EQ(pts[2].values.at("nodes"), "2");
  // 3 nodes is no hypercube: those points carry the reason, the others a configuration.
  for (const auto& p : pts) {
    EXPECT_EQ(p.config.has_value(), p.values.at("nodes") != "3");
    if (!p.config) {
      EXPECT_NE(p.error.find("power of two"), std::string::npos);
    }
  }
  EXPECT_DOUBLE_EQ(pts[1].config->what_ifs.get("latency")->value, 1e-3);
  EXPECT_THROW(split_list("1,,2", "nodes"), UsageError);
  EXPECT_THROW(split_list("", "nodes"), UsageError);
  const auto bad = expand_sweep({{"algorithm", {"elastic"}}, {"packet", {"10"}}}, "x.json");
  EXPECT_FALSE(bad[0].config.has_value()); // --packet does not apply to elastic
}

// Sweeps: the reference's run on one node (scanline for Kurc et al.) is the baseline of the points
// that share every other flag; --baseline adds it where missing.
TEST(Sweep, SpeedupsAgainstTheMatchingReferenceRun) {
  const std::vector<SweepAxis> axes = {
      {"algorithm", {"scanline", "pair-rs"}}, {"nodes", {"1", "4"}}, {"latency", {"10us", "1ms"}}};
  auto pts = expand_sweep(axes, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 8u);
  std::vector<nlohmann::json> reps;
  for (const auto& p : pts)
    reps.push_back({{"status", "ok"},
                    {"nodes", std::stoi(p.values.at("nodes"))},
                    {"virtual_time_s", p.values.at("algorithm") == "scanline" ? 8.0 : 2.0}});
  reps[0]["virtual_time_s"] = 8.0; // scanline, 1 node, 10us
  reps[1]["virtual_time_s"] = 4.0; // scanline, 1 node, 1ms
  auto rows = sweep_rows(axes, pts, reps);
  ASSERT_TRUE(add_speedups(pts, reps, rows));
  // pair-rs, 4 nodes, 1ms (index 7): 4 / 2.
  EXPECT_DOUBLE_EQ(rows[7]["speedup"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(rows[7]["efficiency"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(rows[6]["speedup"].get<double>(), 4.0);

  const std::vector<SweepAxis> no_seq = {{"algorithm", {"pair-rs"}}, {"nodes", {"2", "4"}}};
  auto p2 = expand_sweep(no_seq, kRoot + "/scenes/teapot.json");
  std::vector<nlohmann::json> r2(p2.size(), {{"status", "ok"}, {"virtual_time_s", 1.0}});
  auto rows2 = sweep_rows(no_seq, p2, r2);
  EXPECT_FALSE(add_speedups(p2, r2, rows2));
  add_baselines(no_seq, p2, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(p2.size(), 3u);
  EXPECT_TRUE(is_baseline(p2[2]));
  EXPECT_TRUE(p2[2].config.has_value()) << p2[2].error;
}

// A speed-up divides the timed region (elastic's per-picture loop, docs/papers.md), as zcube run's
// paper line does; a --timed axis is an option of the algorithm, so the baseline does not get it.
TEST(Sweep, SpeedupsDivideTheTimedRegionAndTimedIsAnAlgorithmOption) {
  const std::vector<SweepAxis> axes = {
      {"algorithm", {"elastic"}}, {"nodes", {"4"}}, {"timed", {"picture", "all"}}};
  auto pts = expand_sweep(axes, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 2u);
  add_baselines(axes, pts, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 3u); // one baseline serves both --timed values
  ASSERT_TRUE(is_baseline(pts[2]));
  ASSERT_TRUE(pts[2].config.has_value()) << pts[2].error;
  EXPECT_EQ(pts[2].values.at("timed"), "");
  const std::vector<nlohmann::json> reps = {
      {{"status", "ok"}, {"nodes", 4}, {"virtual_time_s", 3.0}, {"timed_s", 2.0}},
      {{"status", "ok"}, {"nodes", 4}, {"virtual_time_s", 3.0}, {"timed_s", 2.5}},
      {{"status", "ok"}, {"nodes", 1}, {"virtual_time_s", 8.0}}};
  auto rows = sweep_rows(axes, pts, reps);
  ASSERT_TRUE(add_speedups(pts, reps, rows));
  EXPECT_DOUBLE_EQ(rows[0]["virtual_s"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(rows[0]["timed_s"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(rows[0]["speedup"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(rows[1]["speedup"].get<double>(), 3.2);
  EXPECT_DOUBLE_EQ(rows[2]["timed_s"].get<double>(), 8.0); // no timed region: the whole run
}
