// Each paper's speed-up in a sweep (docs/papers.md): the baseline is the algorithm family's own
// reference on one node (sequential, scanline for Kurc et al., node-initiated for Blazek) and the
// speed-up divides the timed region (Kurc et al.: Table 2's three columns on the critical node).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "csv.hpp"
#include "repro/simulate.hpp"
#include "repro/sweep.hpp"
#include "source_root.hpp"

using namespace zc;

namespace {

using test::kRoot;

using test::csv_cell;

// The longest sum of `phases` over the nodes of a report: Table 2's columns on the critical node.
double critical_node_sum(const nlohmann::json& r, const std::vector<std::string>& phases) {
  double longest = 0;
  for (const auto& n : r["per_node"]) {
    double s = 0;
    for (const auto& p : phases)
      s += n["phases"].value(p, 0.0);
    longest = std::max(longest, s);
  }
  return longest;
}

} // namespace

TEST(SweepReference, EachFamilyGetsItsPapersReference) {
  const std::vector<SweepAxis> axes = {
      {"algorithm", {"elastic", "pair-rs", "aapc-hbp", "node-initiated"}}, {"nodes", {"4"}}};
  auto pts = expand_sweep(axes, kRoot + "/scenes/teapot.json");
  add_baselines(axes, pts, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 7u); // pair-rs and aapc-hbp share scanline
  std::vector<std::string> refs;
  for (std::size_t i = 4; i < pts.size(); ++i) {
    ASSERT_TRUE(is_baseline(pts[i]));
    ASSERT_TRUE(pts[i].config.has_value()) << pts[i].error;
    EXPECT_EQ(pts[i].config->nodes, 1);
    refs.push_back(pts[i].config->algorithm);
  }
  EXPECT_EQ(refs, (std::vector<std::string>{"sequential", "scanline", "node-initiated"}));
  // Timed regions: elastic 2 s, Kurc 1 s; Blazek's whole run 3 s. References: 8, 5, 30 s.
  const std::vector<nlohmann::json> reps = {
      {{"status", "ok"}, {"nodes", 4}, {"virtual_time_s", 3.0}, {"timed_s", 2.0}},
      {{"status", "ok"}, {"nodes", 4}, {"virtual_time_s", 3.0}, {"timed_s", 1.0}},
      {{"status", "ok"}, {"nodes", 4}, {"virtual_time_s", 3.0}, {"timed_s", 2.5}},
      {{"status", "ok"}, {"nodes", 4}, {"virtual_time_s", 3.0}},
      {{"status", "ok"}, {"nodes", 1}, {"virtual_time_s", 8.0}},
      {{"status", "ok"}, {"nodes", 1}, {"virtual_time_s", 9.0}, {"timed_s", 5.0}},
      {{"status", "ok"}, {"nodes", 1}, {"virtual_time_s", 30.0}}};
  auto rows = sweep_rows(axes, pts, reps);
  ASSERT_TRUE(add_speedups(pts, reps, rows));
  EXPECT_DOUBLE_EQ(rows[0]["speedup"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(rows[1]["speedup"].get<double>(), 5.0);
  EXPECT_DOUBLE_EQ(rows[2]["speedup"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(rows[3]["speedup"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(rows[5]["speedup"].get<double>(), 1.0);
}

// One speed-up per point, whichever command computes it: a sweep of AAPC-HBP, 2 POT, 640x640 on
// 16 nodes with its reference gives the speed-up results/kurc/speedup.csv holds (zcube
// reproduce), both dividing repro's timed_s.
TEST(SweepReference, KurcSpeedupIsTheOneZcubeReproduceWrote) {
  const std::string scene = kRoot + "/scenes/kurc/2pot.json";
  const std::vector<SweepAxis> axes = {{"machine", {"ipsc2"}},
                                       {"algorithm", {"aapc-hbp"}},
                                       {"nodes", {"16"}},
                                       {"size", {"640x640"}}};
  auto pts = expand_sweep(axes, scene);
  add_baselines(axes, pts, scene);
  ASSERT_EQ(pts.size(), 2u);
  std::vector<RunConfig> cfgs;
  for (const auto& p : pts) {
    ASSERT_TRUE(p.config.has_value()) << p.error;
    cfgs.push_back(*p.config);
  }
  const auto reps = simulate_batch(cfgs, 2);
  auto rows = sweep_rows(axes, pts, reps);
  ASSERT_TRUE(add_speedups(pts, reps, rows));
  ASSERT_TRUE(rows[0]["speedup"].is_number()) << rows[0].dump();
  const double sweep_speedup = rows[0]["speedup"].get<double>();
  int found = 0;
  for (const auto& row : test::read_csv(kRoot + "/results/kurc/speedup.csv"))
    if (row.at("algorithm") == "aapc-hbp" && row.at("scene") == "2pot" &&
        row.at("width") == "640" && row.at("height") == "640" && row.at("nodes") == "16") {
      ++found;
      ASSERT_EQ(row.at("status"), "ok");
      // The CSV prints 4 significant digits.
      EXPECT_NEAR(std::stod(row.at("speedup")), sweep_speedup, 6e-4 * sweep_speedup);
      EXPECT_NEAR(std::stod(row.at("timed_s")), rows[0]["timed_s"].get<double>(), 1e-5);
      EXPECT_NEAR(std::stod(row.at("virtual_s")), rows[0]["virtual_s"].get<double>(), 1e-5);
    }
  EXPECT_EQ(found, 1);
}

// node-initiated on a platform file would run on the file's P nodes, not one: the baseline point
// says so instead of dividing by the wrong run.
TEST(SweepReference, BlazeksReferenceNeedsOneNodeNotAPlatformFile) {
  const std::vector<SweepAxis> axes = {{"machine", {kRoot + "/platforms/volvox-ring-8.xml"}},
                                       {"algorithm", {"host-broadcast"}}};
  auto pts = expand_sweep(axes, kRoot + "/scenes/teapot.json");
  add_baselines(axes, pts, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_TRUE(is_baseline(pts[1]));
  EXPECT_FALSE(pts[1].config.has_value());
  EXPECT_NE(pts[1].error.find("node-initiated"), std::string::npos) << pts[1].error;
  // node-initiated itself on the file runs on its 8 nodes: no baseline either.
  const std::vector<SweepAxis> self = {{"machine", {kRoot + "/platforms/volvox-ring-8.xml"}},
                                       {"algorithm", {"node-initiated"}}};
  auto own = expand_sweep(self, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(own.size(), 1u);
  EXPECT_FALSE(is_baseline(own[0]));
  add_baselines(self, own, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(own.size(), 2u);
  EXPECT_FALSE(own[1].config.has_value());
}

// A Kurc sweep with --baseline: the baseline is scanline on one node, timed_s the Table 2 sum on
// the critical node, and the speed-ups are results/kurc/speedup.csv's.
TEST(SweepReference, KurcSweepDividesScanlineByTheTableTwoColumns) {
  const std::vector<SweepAxis> axes = {{"algorithm", {"pair-rs"}},
                                       {"nodes", {"1", "4"}},
                                       {"scene", {kRoot + "/scenes/kurc/1pot.json"}},
                                       {"size", {"400"}}};
  auto pts = expand_sweep(axes, kRoot + "/scenes/teapot.json");
  add_baselines(axes, pts, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 3u);
  ASSERT_TRUE(pts[2].config.has_value()) << pts[2].error;
  ASSERT_EQ(pts[2].config->algorithm, "scanline");
  const auto reps =
      run_points(pts, [](const std::vector<RunConfig>& c) { return simulate_batch(c, 2); });
  ASSERT_EQ(reps.size(), 3u);
  for (const auto& r : reps)
    ASSERT_EQ(r.value("status", ""), "ok") << r.dump();
  auto rows = sweep_rows(axes, pts, reps);
  ASSERT_TRUE(add_speedups(pts, reps, rows));
  const std::vector<std::string> table2 = {"span_list_creation", "local_zbuffer", "pixel_merging"};
  for (const auto& r : reps) {
    ASSERT_TRUE(r.contains("timed_s")) << r["algorithm"];
    EXPECT_NEAR(r["timed_s"].get<double>(), critical_node_sum(r, table2),
                1e-12 * r["timed_s"].get<double>());
  }
  // The schemes' deal and output are outside the timed region; scanline has neither.
  EXPECT_LT(reps[1]["timed_s"].get<double>(), reps[1]["virtual_time_s"].get<double>() * 0.99);
  const double ref = reps[2]["timed_s"].get<double>();
  EXPECT_DOUBLE_EQ(rows[1]["speedup"].get<double>(), ref / reps[1]["timed_s"].get<double>());
  const std::string csv = kRoot + "/results/kurc/speedup.csv";
  const std::map<std::string, std::string> p1 = {
      {"algorithm", "pair-rs"}, {"scene", "1pot"}, {"width", "400"}, {"nodes", "1"}};
  const std::string committed = csv_cell(csv, p1, "speedup");
  ASSERT_FALSE(committed.empty());
  EXPECT_NEAR(rows[0]["speedup"].get<double>(), std::stod(committed), 6e-5);
  // At 4 nodes too: results/kurc divides the same critical-node time.
  auto p4 = p1;
  p4["nodes"] = "4";
  const std::string timed = csv_cell(csv, p4, "timed_s");
  ASSERT_FALSE(timed.empty());
  EXPECT_NEAR(std::stod(timed), reps[1]["timed_s"].get<double>(),
              1e-5 * reps[1]["timed_s"].get<double>());
  EXPECT_NEAR(std::stod(csv_cell(csv, p4, "speedup")), rows[1]["speedup"].get<double>(),
              6e-4 * rows[1]["speedup"].get<double>());
}
