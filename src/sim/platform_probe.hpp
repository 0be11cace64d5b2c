#pragma once
// Defence in depth against SimGrid's aborts: a platform file that passed zcube's checks is loaded
// once more in a forked child (an engine of its own, the file's settings, the whole of
// read_platform: routes computed, every figure read) before the run's engine loads it. SimGrid
// ends the process (xbt_die, an assertion, a crash) on platforms it finds inconsistent; in the
// child that becomes one InputError naming the file and SimGrid's own reason, never a signal.
// A child that does not finish within kProbeSeconds is ended, and that is an error too.
#include <string>
#include <vector>

namespace zc {

constexpr unsigned kProbeSeconds = 120;

// `settings`: the file's <config> settings as SimGrid arguments ("--cfg=key:value"). Call before
// this process creates a SimGrid engine (a forked child cannot create a second one).
void probe_platform_file(const std::string& path, const std::vector<std::string>& settings);

} // namespace zc
