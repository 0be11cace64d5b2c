// run/batch: a batch of runs in forked processes; a failing point does not lose the others.
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
#include "util/error.hpp"
#include "util/nnls.hpp"

using namespace zc;

namespace {

const std::string kRoot = ZCUBE_SOURCE_DIR;

using test::read_csv;

} // namespace

TEST(Batch, AFailingPointDoesNotLoseTheOthers) {
  SimConfig good;
  good.machine = "ipsc2";
  good.nodes = 2;
  good.algorithm = "elastic";
  good.scene_path = kRoot + "/scenes/teapot.json";
  good.width = good.height = 64;
  SimConfig missing = good;
  missing.scene_path = kRoot + "/no/such/scene.json";
  int calls = 0;
  const auto r =
      simulate_batch({missing, good, missing}, 2, [&](const BatchProgress&) { ++calls; });
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0]["status"], "error");
  EXPECT_NE(r[0]["error"].get<std::string>().find("scene.json"), std::string::npos);
  EXPECT_EQ(r[1]["status"], "ok");
  EXPECT_EQ(r[1]["image"]["identical_to_sequential"], true);
  EXPECT_EQ(r[2]["status"], "error");
  EXPECT_EQ(calls, 3);
}
