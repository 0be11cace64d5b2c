#pragma once
// Quantities with units, written the way SimGrid writes them: "275us", "2.8MBps", "16MiB", "10Mf".
// A bare number is in base units (seconds, bytes per second, bytes). Errors throw UsageError
// naming the flag.
#include <string>

namespace zc {

double parse_time(const std::string& text, const std::string& flag = "time");      // seconds
double parse_bandwidth(const std::string& text, const std::string& flag = "rate"); // bytes/s
double parse_bytes(const std::string& text, const std::string& flag = "size");     // bytes
double parse_speed(const std::string& text, const std::string& flag = "speed"); // flop/s ("10Mf")

// Shortest text that parses back to the same double (for XML and reports).
std::string format_double(double v);

} // namespace zc
