#pragma once
// The user's SimGrid settings (`--cfg name:value`, `--log ...`) checked before any simulation:
// SimGrid reports a bad key with a multi-line dump and a bad model name by aborting the process,
// so they are tried once in a forked child on a one-host platform, and a failure becomes one
// UsageError line.
#include <string>
#include <vector>

namespace zc {

// UsageError naming the first setting SimGrid refuses; nothing when `args` is empty.
void check_simgrid_args(const std::vector<std::string>& args);

} // namespace zc
