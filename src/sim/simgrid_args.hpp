#pragma once
// The user's SimGrid settings (`--cfg name:value`, `--log ...`) checked before any simulation:
// SimGrid reports a bad key with a multi-line dump and a bad model name by aborting the process,
// so they are tried once in a forked child on a one-host platform, and a failure becomes one
// UsageError line.
#include <string>
#include <vector>

namespace zc {

// Empty when `key` is a SimGrid setting zcube runs with and `value` is in its range (a platform
// file's <config> is held to the same list), else why not.
std::string setting_problem(const std::string& key, const std::string& value);

// UsageError naming the first setting SimGrid refuses; nothing when `args` is empty.
void check_simgrid_args(const std::vector<std::string>& args);

} // namespace zc
