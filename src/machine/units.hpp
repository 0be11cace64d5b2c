#pragma once
// Quantities with units, SimGrid's units exactly: "275us", "2.8MBps", "16MiB", "10Mf". The tables
// are SimGrid 3.32's (xbt/parse_units.hpp, src/xbt/xbt_parse_units.cpp), built the same way: a base
// unit, then prefixes by 1000 (k, M, G, T, P, E, Z, Y; or kilo ... yotta for flops) or 1024 (Ki ...
// Yi). This layer links no SimGrid (docs/architecture.md), so the tables are generated here and
// test_machine checks them against xbt_parse_get_* string by string. On top of SimGrid's rules:
// the value must be finite and non-negative, and a bare number is in base units (seconds, bytes per
// second, bytes, flop/s) only where the unit is optional; command-line flags require it (`--latency
// 275` is an error, not 275 seconds). Errors throw UsageError naming the flag and the units.
#include <map>
#include <string>
#include <vector>

namespace zc {

enum class Unit { Optional, Required };

double parse_time(const std::string& text, const std::string& flag = "time",
                  Unit unit = Unit::Optional); // seconds
double parse_bandwidth(const std::string& text, const std::string& flag = "rate",
                       Unit unit = Unit::Optional); // bytes/s
double parse_bytes(const std::string& text, const std::string& flag = "size",
                   Unit unit = Unit::Optional); // bytes
// Comma-separated sizes, each with its unit ("0B,64B,1KiB"): --sizes of zcube pingpong.
std::vector<double> parse_bytes_list(const std::string& text, const std::string& flag);
double parse_speed(const std::string& text, const std::string& flag = "speed",
                   Unit unit = Unit::Optional); // flop/s ("10Mf")

// SimGrid's tables: unit -> factor to the base unit (s, B/s, B, flop/s).
using UnitTable = std::map<std::string, double>;
const UnitTable& time_units();
const UnitTable& bandwidth_units();
const UnitTable& size_units();
const UnitTable& speed_units();

// Shortest text that parses back to the same double (for XML and reports).
std::string format_double(double v);

} // namespace zc
