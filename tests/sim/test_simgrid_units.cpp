// sim: speeds written the way SimGrid writes them.
#include <bit>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <unistd.h>

#include <gtest/gtest.h>
#include <simgrid/s4u.hpp>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "machine/topology.hpp"
#include "machine/units.hpp"
#include "sim_fixtures.hpp"
#include "util/error.hpp"

using namespace zc;
using namespace zc::test;

TEST(Units, SpeedsTheWaySimGridWritesThem) {
  EXPECT_DOUBLE_EQ(parse_speed("10Mf"), 10e6);
  EXPECT_DOUBLE_EQ(parse_speed("1Gf"), 1e9);
  EXPECT_DOUBLE_EQ(parse_speed("2.5kf"), 2500);
  EXPECT_THROW(parse_speed("10MHz", "--speed"), UsageError);
  EXPECT_DOUBLE_EQ(parse_time("0us"), 0);
  EXPECT_DOUBLE_EQ(parse_bytes("8MiB"), 8.0 * 1048576);
}
