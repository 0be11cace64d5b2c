// The committed calibration (results/calibration/, written by `zcube calibrate --write`) keeps the
// promises of docs/machines.md: every fitted cost within its plausible range of the physical
// estimate, the multipliers in the header equal to the committed fit, the validation tables there
// and the cross-validation's median error within the 10 % the model is held to.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "machine/cpu_model.hpp"
#include "machine/machine.hpp"
#include "repro/paper_figures.hpp"

using namespace zc;

namespace {

const std::string kDir = std::string(ZCUBE_SOURCE_DIR) + "/results/calibration";

nlohmann::json committed_fit() {
  std::ifstream f(kDir + "/fit.json");
  if (!f) return nullptr;
  return nlohmann::json::parse(f);
}

} // namespace

TEST(CommittedCalibration, EveryFittedCostIsWithinItsPlausibleRange) {
  const auto fit = committed_fit();
  ASSERT_TRUE(fit.is_object()) << kDir << "/fit.json missing";
  ASSERT_FALSE(fit["plausibility"].empty());
  for (const auto& r : fit["plausibility"]) {
    const double ratio = r["ratio"].get<double>();
    EXPECT_GE(ratio, plausible_low() * (1 - 1e-12)) << r.dump();
    EXPECT_LE(ratio, plausible_high() * (1 + 1e-12)) << r.dump();
  }
}

TEST(CommittedCalibration, TheHeaderHoldsTheCommittedMultipliers) {
  const auto fit = committed_fit();
  ASSERT_TRUE(fit.is_object());
  const auto k = calibrated_group_scale();
  ASSERT_EQ(fit["scale"].size(), k.size());
  for (std::size_t g = 0; g < k.size(); ++g)
    EXPECT_NEAR(fit["scale"][g].get<double>(), k[g], 1e-12 * k[g]) << g;
}

TEST(CommittedCalibration, CrossValidationCoversEverySceneAndPredictsWithin10Percent) {
  const auto fit = committed_fit();
  ASSERT_TRUE(fit.is_object());
  ASSERT_TRUE(fit.contains("crossval"));
  const auto& folds = fit["crossval"]["folds"];
  ASSERT_EQ(folds.size(), kurc_scenes().size());
  std::vector<double> errs;
  for (const auto& f : folds) {
    EXPECT_EQ(f["targets"].size(), 6u) << f["fold"];
    for (const auto& t : f["targets"]) {
      EXPECT_NE(t["id"].get<std::string>().find(f["fold"].get<std::string>()), std::string::npos);
      errs.push_back(std::fabs(t["rel_error"].get<double>()));
    }
  }
  std::sort(errs.begin(), errs.end());
  const double median = 0.5 * (errs[errs.size() / 2 - 1] + errs[errs.size() / 2]);
  EXPECT_NEAR(median, fit["crossval"]["median_abs_rel_error"].get<double>(), 1e-12);
  EXPECT_LE(median, 0.10);
}

TEST(CommittedCalibration, CharlesSpeedupsArePredictionsBesideThePapersFigures) {
  const auto fit = committed_fit();
  ASSERT_TRUE(fit.is_object());
  ASSERT_EQ(fit["charles"].size(), charles_teapot_speedups().size());
  for (std::size_t i = 0; i < fit["charles"].size(); ++i) {
    const auto& r = fit["charles"][i];
    EXPECT_EQ(r["paper"].get<double>(), charles_teapot_speedups()[i].speedup);
    EXPECT_GT(r["predicted"].get<double>(), 1.0);
  }
  // No Charles figure is a fitted target.
  for (const auto& t : fit["targets"])
    EXPECT_EQ(t["id"].get<std::string>().rfind("kurc/", 0), 0u) << t["id"];
}
