#pragma once
// The slowest costs the simulated clock can time. The clock is a double: beyond 2^52 ns of virtual
// time it no longer resolves the simulated CPU's nanoseconds and compute times are rounded (a
// 1e300 s latency made every compute phase 0 s). A start-up or per-hop cost above an hour, or a
// channel below a byte a second, gets there within a few messages; physical machines sit far
// inside. The what-if flags (run/run_flags.cpp) and a platform file's links (sim/platform_load.cpp)
// are held to these bounds.
namespace zc {

constexpr double kMaxDelay_s = 3600;        // a message start-up, a per-hop cost: at most 1 h
constexpr double kMinBandwidth_Bps = 1.0;   // a channel's bandwidth: at least 1 B/s
constexpr double kClockResolvedNs = 0x1p52; // virtual nanoseconds the clock resolves one by one

} // namespace zc
