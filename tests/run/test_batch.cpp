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

// An elastic run of the teapot at 64x64.
RunConfig small_elastic(int nodes) {
  RunConfig c;
  c.machine = "ipsc2";
  c.nodes = nodes;
  c.algorithm = "elastic";
  c.scene_path = kRoot + "/scenes/teapot.json";
  c.width = c.height = 64;
  return c;
}

} // namespace

TEST(Batch, AFailingPointDoesNotLoseTheOthers) {
  const RunConfig good = small_elastic(2);
  RunConfig missing = good;
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

// A point's report tells what its whole process cost the host (fork to exit), as the kernel
// accounts it: CPU time, the part of it in the kernel, and minor page faults.
TEST(Batch, AReportCarriesItsProcesssHostCost) {
  const auto r = simulate_batch({small_elastic(4)}, 1);
  ASSERT_EQ(r.size(), 1u);
  ASSERT_EQ(r[0]["status"], "ok");
  const nlohmann::json& h = r[0]["host"];
  ASSERT_TRUE(h.contains("process_cpu_s") && h.contains("process_kernel_s") &&
              h.contains("process_minor_faults"));
  EXPECT_GE(h["process_kernel_s"].get<double>(), 0.0);
  EXPECT_LE(h["process_kernel_s"].get<double>(), h["process_cpu_s"].get<double>());
  // A forked process writes to at least one page of its own (its stack, its report).
  EXPECT_GT(h["process_minor_faults"].get<long>(), 0);
}
