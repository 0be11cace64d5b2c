// The compositing layer: every strategy of the registry on every representation composites the
// sequential renderer's picture on every node count from 1 to 64 it accepts (odd ones on a ring),
// and the strategies that generalise others agree with them.
#include <gtest/gtest.h>

#include "algo/algorithm.hpp"
#include "algo/sort_last/compositing_study.hpp"
#include "compositing/strategy.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

const char* kPictures[] = {"dense", "winning-pixels", "run-length"};

std::vector<const Algorithm*> sort_last_algorithms() {
  std::vector<const Algorithm*> v;
  for (const auto& a : algorithms())
    if (a.name.rfind("sort-last-", 0) == 0) v.push_back(&a);
  return v;
}

nlohmann::json run(const Algorithm& a, const std::string& picture, int P, int size,
                   const std::string& radix = "", bool compare = true) {
  const bool cube = (P & (P - 1)) == 0;
  RunConfig c = sim_config("ipsc2", P, cube ? Topology::Cube : Topology::Ring, Fidelity::Circuit);
  c.algorithm = a.name;
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/kurc/2pot.json";
  c.width = size;
  c.height = size * 3 / 4;
  c.compare_with_sequential = compare;
  c.options.values["picture"] = picture;
  if (!radix.empty()) c.options.values["radix"] = radix;
  validate_options(a, c.options, cube);
  c.what_ifs.set("memory", {64.0 * 1048576});
  return run_simulation_isolated(c);
}

bool accepts(const Algorithm& a, const std::string& radix, int P) {
  AlgorithmOptions o;
  if (!radix.empty()) o.values["radix"] = radix;
  validate_options(a, o, true);
  try {
    if (a.check_nodes) a.check_nodes(o, P);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

double merging_s(const nlohmann::json& r) {
  for (const auto& p : r["phases"])
    if (p["name"] == "pixel_merging") return p["max_s"].get<double>();
  return -1;
}

} // namespace

TEST(Compositing, TheRegistryHasEveryStrategy) {
  EXPECT_EQ(sort_last_algorithms().size(), compositing::strategies().size());
  EXPECT_GE(compositing::strategies().size(), 5u);
}

TEST(Compositing, EveryStrategyAndPictureGivesTheSequentialImageOn1To64Nodes) {
  for (const Algorithm* a : sort_last_algorithms())
    for (const char* picture : kPictures)
      for (int P = 1; P <= 64; ++P) {
        if (!accepts(*a, "", P)) continue;
        auto r = run(*a, picture, P, 40);
        ASSERT_EQ(r["status"], "ok") << a->name << " " << picture << " P=" << P << r.dump();
        EXPECT_EQ(r["image"]["identical_to_sequential"], true)
            << a->name << " " << picture << " P=" << P;
      }
}

TEST(Compositing, RadixKWithTwoIsBinarySwapAndWithPIsDirectSend) {
  const Algorithm& radix = find_algorithm("sort-last-radix-k");
  for (const char* picture : kPictures)
    for (int P : {4, 16}) {
      const double k2 = merging_s(run(radix, picture, P, 96, "2", false));
      const double kp = merging_s(run(radix, picture, P, 96, std::to_string(P), false));
      EXPECT_EQ(k2,
                merging_s(run(find_algorithm("sort-last-binary-swap"), picture, P, 96, "", false)))
          << picture << " P=" << P;
      EXPECT_EQ(kp,
                merging_s(run(find_algorithm("sort-last-direct-send"), picture, P, 96, "", false)))
          << picture << " P=" << P;
    }
}

TEST(Compositing, RadixRounds) {
  using compositing::radix_rounds;
  EXPECT_EQ(radix_rounds(16, {2}), (std::vector<int>{2, 2, 2, 2}));
  EXPECT_EQ(radix_rounds(16, {4}), (std::vector<int>{4, 4}));
  EXPECT_EQ(radix_rounds(32, {4}), (std::vector<int>{4, 4, 2}));
  EXPECT_EQ(radix_rounds(12, {4}), (std::vector<int>{4, 3}));
  EXPECT_EQ(radix_rounds(7, {4}), (std::vector<int>{7}));
  EXPECT_EQ(radix_rounds(24, {2, 3}), (std::vector<int>{2, 3, 4}));
  EXPECT_TRUE(radix_rounds(24, {5, 2}).empty());
  EXPECT_TRUE(radix_rounds(8, {1}).empty());
}

TEST(Compositing, TheStudyTimesEveryContenderFromOneRendering) {
  RunConfig c = sim_config("ipsc2", 16, Topology::Cube, Fidelity::Circuit);
  c.algorithm = "compositing-study";
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/kurc/2pot.json";
  c.width = c.height = 96;
  c.what_ifs.set("memory", {64.0 * 1048576});
  const auto r = run_simulation_isolated(c);
  ASSERT_EQ(r["status"], "ok") << r.dump();
  const auto names = compositing_contenders(16);
  for (const char* want :
       {"pair-rs", "aapc-hbp", "binary-swap", "direct-send", "radix-4", "radix-8"})
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  for (const auto& name : names) {
    double s = -1;
    for (const auto& p : r["phases"])
      if (p["name"] == name) s = p["max_s"].get<double>();
    EXPECT_GT(s, 0) << name;
    EXPECT_GT(r["compositing_study"][name]["max_messages"].get<double>(), 0) << name;
  }
  // One start-up a stage: binary swap's busiest node makes log2 16 = 4, direct send's 15.
  EXPECT_EQ(r["compositing_study"]["binary-swap"]["max_messages"].get<double>(), 4);
  EXPECT_EQ(r["compositing_study"]["direct-send"]["max_messages"].get<double>(), 15);
}
