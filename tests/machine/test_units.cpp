// zcube's units are SimGrid's: every string SimGrid 3.32's own parser (xbt_parse_get_*) reads as a
// non-negative finite quantity, zcube reads as the same number; every unit SimGrid refuses, zcube
// refuses (machine/units.hpp).
#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <simgrid/Exception.hpp>
#include <xbt/parse_units.hpp>

#include "machine/units.hpp"
#include "util/error.hpp"

namespace {

using ZcubeParse = double (*)(const std::string&, const std::string&, zc::Unit);
using SimGridParse = double (*)(const std::string&, int, const std::string&, const std::string&);

std::optional<double> simgrid_reads(SimGridParse parse, const std::string& text) {
  try {
    return parse("test", 0, text, ""); // no entity kind: no warning for a bare number
  } catch (const simgrid::ParseError&) {
    return std::nullopt;
  }
}

std::optional<double> zcube_reads(ZcubeParse parse, const std::string& text) {
  try {
    return parse(text, "--flag", zc::Unit::Required);
  } catch (const zc::UsageError&) {
    return std::nullopt;
  }
}

struct Kind {
  const char* name;
  ZcubeParse zcube;
  SimGridParse simgrid;
  const zc::UnitTable& table;
};

std::vector<Kind> kinds() {
  return {{"time", zc::parse_time, xbt_parse_get_time, zc::time_units()},
          {"bandwidth", zc::parse_bandwidth, xbt_parse_get_bandwidth, zc::bandwidth_units()},
          {"size", zc::parse_bytes, xbt_parse_get_size, zc::size_units()},
          {"speed", zc::parse_speed, xbt_parse_get_speed, zc::speed_units()}};
}

// Units of every kind, and look-alikes SimGrid refuses (KBps, Kbps, kflops, Mflops, sec, ...).
std::vector<std::string> candidate_units() {
  std::vector<std::string> units = {"KBps", "Kbps",  "KB", "Kb", "kflops", "Mflops", "Gflops",
                                    "sec",  "S",     "MS", "Us", "mbps",   "mBps",   "kib",
                                    "KIB",  "bytes", "B ", " B", "Bps/s",  "f/s",    "x"};
  for (const Kind& k : kinds())
    for (const auto& [u, f] : k.table)
      units.push_back(u);
  return units;
}

TEST(Units, SameAsSimGridsParserForEveryUnit) {
  const std::vector<std::string> numbers = {"0", "1", "2.8", "275", "1e-3", "1.5e6", ".5", "16"};
  int compared = 0;
  for (const Kind& k : kinds())
    for (const std::string& u : candidate_units())
      for (const std::string& n : numbers) {
        const std::string text = n + u;
        const auto sg = simgrid_reads(k.simgrid, text);
        const auto zc = zcube_reads(k.zcube, text);
        ASSERT_EQ(sg.has_value(), zc.has_value())
            << k.name << " '" << text << "': SimGrid " << (sg ? "reads" : "refuses")
            << " it, zcube " << (zc ? "reads" : "refuses") << " it";
        if (sg) {
          EXPECT_EQ(*sg, *zc) << k.name << " '" << text << "'";
        }
        ++compared;
      }
  EXPECT_GT(compared, 1000);
}

TEST(Units, KBpsRefusedTBpsAndDaysAcceptedAsBySimGrid) {
  // SimGrid refuses KBps and accepts TBps and d: so does zcube.
  EXPECT_THROW(zc::parse_bandwidth("1KBps", "--bandwidth"), zc::UsageError);
  EXPECT_EQ(zc::parse_bandwidth("1TBps", "--bandwidth"), 1e12);
  EXPECT_EQ(zc::parse_time("1d", "--latency"), 86400);
  EXPECT_EQ(zc::parse_bytes("1KiB", "--memory"), 1024);
  EXPECT_EQ(zc::parse_bytes("8b", "--memory"), 1);
}

TEST(Units, ZcubesOwnRulesOnTop) {
  // A flag needs its unit; negative, infinite and out-of-range values are refused.
  EXPECT_THROW(zc::parse_time("275", "--latency", zc::Unit::Required), zc::UsageError);
  EXPECT_EQ(zc::parse_time("275", "--latency", zc::Unit::Optional), 275);
  for (const char* bad : {"-1s", "infs", "nans", "1e400s", "1e-400s", "s", ""})
    EXPECT_THROW(zc::parse_time(bad, "--latency"), zc::UsageError) << bad;
  try {
    zc::parse_bandwidth("1KBps", "--bandwidth");
  } catch (const zc::UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--bandwidth '1KBps': unknown unit 'KBps'"),
              std::string::npos)
        << e.what();
  }
}

} // namespace
