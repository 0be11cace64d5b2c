// machine/cpu_model: an operation's cost is its instruction mix at the documented clocks.
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

TEST(CpuModel, AVertexTransformCostsItsInstructionMixAtTheDocumentedClocks) {
  // Hand sum of machines/cpu/operations.json's vertex mix at the 80387's clocks.
  const CpuModel& c = cpu_model("i80386");
  const double expect = 16 * 20 + 38 * 33 + 27 * 28 + 16 * 44 + 2 * 89 + 125 + 7 * 40 + 15 * 2 +
                        6 * 4 + 4 * 2 + 8 * 8 + 40;
  EXPECT_DOUBLE_EQ(c.cycles.vertices_transformed, expect);
  EXPECT_DOUBLE_EQ(c.clock_hz, 16e6);
  EXPECT_DOUBLE_EQ(cpu_seconds(c).vertices_transformed, expect / 16e6);
  EXPECT_EQ(c.cycles.pixels_final, 0);
  // A memory copy stays within the bus bounds of docs/machines.md: 5-16 MB/s on the 16 MHz 386,
  // tens of MB/s on the i860.
  EXPECT_GT(1 / cpu_seconds(c).bytes_packed, 5e6);
  EXPECT_LT(1 / cpu_seconds(c).bytes_packed, 16e6);
  EXPECT_GT(1 / cpu_seconds(cpu_model("i860xr")).bytes_packed, 20e6);
  EXPECT_THROW(cpu_model("z80"), UsageError);
}
