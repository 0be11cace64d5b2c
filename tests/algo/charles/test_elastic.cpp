// Charles, Lefevre, Miguet 1995 on the simulated iPSC/860 and Volvox: the image of every
// configuration is the sequential renderer's, the elastic slices balance the estimated load, the
// request variant moves fewer bytes than the multi-broadcast.
#include <map>

#include <gtest/gtest.h>

#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

nlohmann::json elastic(const std::string& scene, int P, Topology t, const std::string& vertices,
                       int frames = 1, int size = 96, const std::string& machine = "ipsc860") {
  RunConfig c = sim_config(machine, P, t, Fidelity::Circuit);
  c.algorithm = "elastic";
  c.scene_path = scene;
  c.width = c.height = size;
  c.options.frames = frames;
  c.options.values["vertices"] = vertices;
  c.compare_with_sequential = true;
  return run_simulation_isolated(c);
}

const std::string kTeapot = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";

} // namespace

TEST(Elastic, ImageIsSequentialOnEveryCube) {
  for (int P : {1, 2, 4, 8, 16, 32})
    for (const char* v : {"broadcast", "request"}) {
      auto r = elastic(kTeapot, P, Topology::Cube, v);
      ASSERT_EQ(r["status"], "ok") << r.dump();
      EXPECT_EQ(r["image"]["identical_to_sequential"], true) << "P=" << P << " " << v;
    }
}

TEST(Elastic, ImageIsSequentialOnEveryRing) {
  for (int P : {2, 3, 4, 5, 8, 16})
    for (const char* v : {"broadcast", "request"}) {
      auto r = elastic(kTeapot, P, Topology::Ring, v, 1, 96, "volvox");
      ASSERT_EQ(r["status"], "ok") << r.dump();
      EXPECT_EQ(r["image"]["identical_to_sequential"], true) << "P=" << P << " " << v;
    }
}

TEST(Elastic, AnimationFramesAreAllSequential) {
  for (const char* v : {"broadcast", "request"}) {
    auto r = elastic(kTeapot, 8, Topology::Cube, v, 4);
    ASSERT_EQ(r["status"], "ok") << r.dump();
    EXPECT_EQ(r["image"]["identical_to_sequential"], true) << v;
    EXPECT_EQ(r["image"]["frames_sha256"].size(), 4u);
    // The scatters happen once, the per-frame phases every frame.
    auto one = elastic(kTeapot, 8, Topology::Cube, v, 1);
    EXPECT_GT(r["virtual_time_s"].get<double>(), 3 * one["virtual_time_s"].get<double>() / 2);
  }
}

TEST(Elastic, SlicesBalanceTheEstimatedLoadAndDuplicateCrossingTriangles) {
  auto r = elastic(kTeapot, 4, Topology::Cube, "broadcast", 1, 256);
  ASSERT_EQ(r["status"], "ok");
  const auto& e = r["elastic"];
  std::int64_t total = 0, mx = 0, mn = INT64_MAX;
  for (const auto& s : e["slices"]) {
    total += s["workload"].get<std::int64_t>();
    mx = std::max(mx, s["workload"].get<std::int64_t>());
    mn = std::min(mn, s["workload"].get<std::int64_t>());
  }
  // Each slice within one row's load of the ideal: two slices differ by at most two rows' loads,
  // and a teapot row holds well under 100 triangles at 256 rows.
  EXPECT_LE(mx - mn, 2 * e["max_row_load"].get<std::int64_t>());
  EXPECT_GT(e["duplicated_triangles"].get<std::int64_t>(), 0); // Table 1: 4238 > 3572
  EXPECT_EQ(e["triangles_rendered"].get<std::int64_t>(),
            3751 + e["duplicated_triangles"].get<std::int64_t>());
  // MultiScatter writes every record it sends field by field and reads every one it receives.
  std::uint64_t records = 0;
  for (const auto& n : r["per_node"])
    records +=
        n["phase_work"]["multiscatter_triangles"].value("triangles_packed", std::uint64_t(0));
  EXPECT_EQ(records, 2 * e["triangles_rendered"].get<std::uint64_t>());
}

TEST(Elastic, RequestMovesFewerBytesThanBroadcastOnTheBone) {
  const std::string bone = std::string(ZCUBE_SOURCE_DIR) + "/scenes/bone.json";
  auto b = elastic(bone, 16, Topology::Cube, "broadcast", 1, 128);
  auto q = elastic(bone, 16, Topology::Cube, "request", 1, 128);
  ASSERT_EQ(b["status"], "ok");
  ASSERT_EQ(q["status"], "ok");
  EXPECT_EQ(q["image"]["sha256"], b["image"]["sha256"]);
  EXPECT_LT(q["communication"]["bytes"].get<double>(), b["communication"]["bytes"].get<double>());
}

TEST(Elastic, EmptySceneAndOneScanlineFinish) {
  const std::string dir = std::string(ZCUBE_SOURCE_DIR) + "/tests/data/sim/";
  for (int P : {1, 4, 16}) {
    auto e = elastic(dir + "empty.json", P, Topology::Cube, "broadcast", 1, 48);
    ASSERT_EQ(e["status"], "ok") << e.dump();
    EXPECT_EQ(e["image"]["identical_to_sequential"], true);
    auto o = elastic(dir + "one_row.json", P, Topology::Cube, "request", 2, 96);
    ASSERT_EQ(o["status"], "ok") << o.dump();
    EXPECT_EQ(o["image"]["identical_to_sequential"], true);
    // All the estimated load is on one row, so on one node.
    std::int64_t total = 0, nonzero = 0;
    for (const auto& sl : o["elastic"]["slices"]) {
      total += sl["workload"].get<std::int64_t>();
      nonzero += sl["workload"].get<std::int64_t>() > 0;
    }
    EXPECT_GT(total, 0);
    EXPECT_EQ(o["elastic"]["max_row_load"].get<std::int64_t>(), total);
    EXPECT_EQ(nonzero, 1);
  }
}

// §4 "write the image to an output device" and §6 "the communication volume is independent of
// the resolution": with --output device no picture travels; with --output gather node 0 receives
// every other slice's colours. Both give the sequential image.
TEST(Elastic, OutputDeviceSendsNoPictureAndGatherSendsTheOtherSlices) {
  for (int size : {96, 192}) {
    std::map<std::string, nlohmann::json> r;
    for (const char* out : {"device", "gather"}) {
      RunConfig c = sim_config("ipsc860", 4, Topology::Cube, Fidelity::Circuit);
      c.algorithm = "elastic";
      c.scene_path = kTeapot;
      c.width = c.height = size;
      c.options.values["output"] = out;
      c.compare_with_sequential = true;
      r[out] = run_simulation_isolated(c);
      ASSERT_EQ(r[out]["status"], "ok") << r[out].dump();
      EXPECT_EQ(r[out]["image"]["identical_to_sequential"], true) << out << " " << size;
    }
    const auto& slices = r["gather"]["elastic"]["slices"];
    std::uint64_t other_rows = 0;
    for (const auto& s : slices)
      if (s["node"] != 0) other_rows += s["rows"].get<std::uint64_t>();
    const std::uint64_t picture = 3 * other_rows * std::uint64_t(size);
    // A binomial-tree gather forwards some slices twice: at least the picture, less than twice.
    const std::uint64_t extra = r["gather"]["communication"]["bytes"].get<std::uint64_t>() -
                                r["device"]["communication"]["bytes"].get<std::uint64_t>();
    EXPECT_GE(extra, picture) << size;
    EXPECT_LT(extra, 2 * picture) << size;
  }
}
