// repro/sweep_design: the designs of a study (grid, one factor at a time, a file of points), the
// checks before any point runs, and the what-if columns of a row.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "repro/sweep_design.hpp"
#include "source_root.hpp"
#include "util/error.hpp"

using namespace zc;
using test::kRoot;

namespace {

const std::string kTeapot = kRoot + "/scenes/teapot.json";

// A file under the temporary directory, removed when the test ends.
struct TempFile {
  std::string path;
  TempFile(const std::string& name, const std::string& text)
      : path((std::filesystem::temp_directory_path() / ("zcube_sweep_design_" + name)).string()) {
    std::ofstream(path) << text;
  }
  ~TempFile() { std::filesystem::remove(path); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
};

} // namespace

TEST(SweepDesign, OneAtATimeVariesOneFlagAroundTheBase) {
  const std::vector<SweepAxis> axes = {{"nodes", {"16", "8", "32"}},
                                       {"latency", {"x1", "x0.1", "x10"}},
                                       {"cpu-scale", {"1", "0.25"}}};
  const auto pts = expand_one_at_a_time(axes, kTeapot);
  ASSERT_EQ(pts.size(), 6u); // 1 + 2 + 2 + 1
  const std::map<std::string, std::string> base = {
      {"nodes", "16"}, {"latency", "x1"}, {"cpu-scale", "1"}};
  EXPECT_EQ(pts[0].values, base);
  for (std::size_t i = 1; i < pts.size(); ++i) {
    int differ = 0;
    for (const auto& [k, v] : base)
      differ += pts[i].values.at(k) != v;
    EXPECT_EQ(differ, 1) << "point " << i;
    ASSERT_TRUE(pts[i].config) << pts[i].error;
  }
  EXPECT_EQ(pts[2].values.at("nodes"), "32");
  EXPECT_EQ(pts[5].values.at("cpu-scale"), "0.25");
}

TEST(SweepDesign, APointFileGivesItsRowsAndItsAxes) {
  const TempFile file("points.csv", "algorithm,nodes,latency\n"
                                    "pair-rs,16,x0.1\n"
                                    "\n"
                                    "aapc-hbp, 16 ,275us\n"
                                    "scanline,1,\n");
  const PointFile f = read_point_file(file.path, kTeapot);
  ASSERT_EQ(f.points.size(), 3u);
  ASSERT_EQ(f.axes.size(), 3u);
  EXPECT_EQ(f.axes[0].flag, "algorithm");
  EXPECT_EQ(f.axes[2].values, (std::vector<std::string>{"x0.1", "275us", ""}));
  ASSERT_TRUE(f.points[1].config) << f.points[1].error;
  EXPECT_EQ(f.points[1].config->nodes, 16);
  ASSERT_TRUE(f.points[2].config) << f.points[2].error;
  EXPECT_FALSE(f.points[2].config->what_ifs.get("latency")); // an empty cell: not given
  EXPECT_TRUE(f.points[0].config->what_ifs.get("latency")->relative);
}

TEST(SweepDesign, ABadPointFileNamesItsLine) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"nodes,speed\n1,2\n", ":1: 'speed' is not a zcube run flag"},
      {"nodes,nodes\n1,2\n", ":1: the flag 'nodes' appears twice"},
      {"nodes,latency\n1,x0.1\n2\n", ":3: 1 cells, the header has 2"},
      {"nodes\n\"1\"\n", ":2: quoted cells"},
      {"nodes\n", "no points"}};
  for (const auto& [text, want] : bad)
    try {
      const TempFile bad_file("bad.csv", text);
      read_point_file(bad_file.path, kTeapot);
      ADD_FAILURE() << text << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
    }
  EXPECT_THROW(read_point_file("/nonexistent/points.csv", kTeapot), InputError);
}

// A missing or malformed scene is one error before anything runs, naming the file.
TEST(SweepDesign, InputsAreCheckedBeforeAnyPointRuns) {
  const auto pts =
      expand_sweep({{"nodes", {"1", "2"}}, {"scene", {"no/such/scene.json"}}}, kTeapot);
  ASSERT_TRUE(pts[0].config);
  try {
    check_point_inputs(pts);
    ADD_FAILURE() << "a missing scene passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no/such/scene.json"), std::string::npos) << e.what();
  }
  const TempFile bad("bad_scene.json", "{\"triangles\": [1, 2");
  EXPECT_THROW(check_point_inputs(expand_sweep({{"scene", {bad.path}}}, kTeapot)), InputError);
  EXPECT_NO_THROW(check_point_inputs(expand_sweep({{"nodes", {"1", "2"}}}, kTeapot)));
}

// A bundled file named as in the checkout is found by the locator, the row keeps the text given.
TEST(SweepDesign, TheLocatorFindsFilesAndTheRowKeepsTheText) {
  const Locate locate = [](const std::string& f) { return kRoot + "/" + f; };
  const auto pts =
      expand_sweep({{"scene", {"scenes/kurc/1pot.json"}}}, "scenes/teapot.json", locate);
  ASSERT_TRUE(pts[0].config) << pts[0].error;
  EXPECT_EQ(pts[0].config->scene_path, kRoot + "/scenes/kurc/1pot.json");
  EXPECT_EQ(pts[0].values.at("scene"), "scenes/kurc/1pot.json");
  EXPECT_NO_THROW(check_point_inputs(pts));
}

TEST(SweepDesign, WhatIfColumnsCarryNumericTwins) {
  nlohmann::json row;
  add_axis_columns(row, "latency", "27.5us");
  add_axis_columns(row, "bandwidth", "x4");
  add_axis_columns(row, "nodes", "16");
  add_axis_columns(row, "cpu-scale", "0.25");
  EXPECT_DOUBLE_EQ(row["latency_s"].get<double>(), 27.5e-6);
  EXPECT_TRUE(row["latency_factor"].is_null());
  EXPECT_TRUE(row["bandwidth_Bps"].is_null());
  EXPECT_EQ(row["bandwidth_factor"], 4.0);
  EXPECT_EQ(row["nodes"], 16); // a number, not "16"
  EXPECT_EQ(row["cpu_scale"], 0.25);
  EXPECT_EQ(row["latency"], "27.5us");
}
