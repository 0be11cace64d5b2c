#pragma once
// Quantities with units, written the way SimGrid writes them: "275us", "2.8MBps", "16MiB", "10Mf".
// A bare number is in base units (seconds, bytes per second, bytes) unless the unit is required
// (command-line flags: `--latency 275` is an error, not 275 seconds). Errors throw UsageError
// naming the flag and the units it takes. (SimGrid's own xbt_parse_get_* take the same units but
// end the process on a bad string, so they cannot give a one-line usage error.)
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

// Shortest text that parses back to the same double (for XML and reports).
std::string format_double(double v);

} // namespace zc
