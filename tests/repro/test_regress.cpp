// repro/regress: reduced reports compared with golden ones, and bad overrides refused.
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

TEST(Regress, ReportsEveryChangedQuantityAndMissingRuns) {
  std::map<std::string, nlohmann::json> a = {
      {"x", {{"virtual_time_s", 2.0}, {"image", {{"sha256", "ab"}}}}},
      {"y", {{"virtual_time_s", 1.0}}}};
  EXPECT_TRUE(compare_reduced(a, a).empty());
  auto b = a;
  b["x"]["virtual_time_s"] = 2.0000000000000004; // one ulp is a change
  b["x"]["image"]["sha256"] = "cd";
  b.erase("y");
  b["z"] = nlohmann::json::object();
  const auto d = compare_reduced(a, b);
  ASSERT_EQ(d.size(), 4u);
  std::set<std::string> what;
  for (const auto& e : d)
    what.insert(e.run + ":" + e.quantity);
  EXPECT_TRUE(what.count("x:virtual_time_s"));
  EXPECT_TRUE(what.count("x:image.sha256"));
  EXPECT_TRUE(what.count("y:(run)"));
  EXPECT_TRUE(what.count("z:(run)"));
}

// A tolerance for rounding noise (4.2e-16 was once reported as a "difference"); a run whose status
// changed is one row, and a side that lacks a sub-report gives one row per value, never a blob.
TEST(Regress, RelativeToleranceAndOneRowPerValue) {
  std::map<std::string, nlohmann::json> a = {
      {"x", {{"status", "ok"}, {"virtual_time_s", 2.0}, {"phases", {{"merge", 1.0}}}}},
      {"y", {{"status", "ok"}, {"virtual_time_s", 1.0}}}};
  auto b = a;
  b["x"]["virtual_time_s"] = 2.0 * (1 + 4.2e-16);
  EXPECT_EQ(compare_reduced(a, b, 0).size(), 1u);
  EXPECT_TRUE(compare_reduced(a, b, 1e-9).empty());
  b["x"]["virtual_time_s"] = 2.0 * (1 + 1e-6);
  EXPECT_EQ(compare_reduced(a, b, 1e-9).size(), 1u);
  b = a;
  b["y"] = {{"status", "error"}, {"error", "node 3 lost"}};
  auto d = compare_reduced(a, b, 1e-9);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].quantity, "status");
  EXPECT_EQ(d[0].after, "error (node 3 lost)");
  b = a;
  b["x"].erase("phases");
  d = compare_reduced(a, b, 1e-9);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].quantity, "phases.merge");
  EXPECT_EQ(d[0].before, "1.0");
  EXPECT_EQ(d[0].after, "(none)");
  EXPECT_EQ(failed_runs({{"y", {{"status", "error"}, {"error", "why"}}}}).size(), 1u);
}

// --set with a key that is no run flag, or a value no run accepts, fails before anything runs.
TEST(Regress, BadOverridesAreUsageErrors) {
  const std::vector<RegressRun> runs = {{"seq", {{"algorithm", "sequential"}}}};
  EXPECT_THROW(run_regress(runs, kRoot, 1, {{"bogus", "1"}}), UsageError);
  try {
    run_regress(runs, kRoot, 1, {{"latency", "5parsecs"}});
    ADD_FAILURE() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("5parsecs"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}
