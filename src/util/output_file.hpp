#pragma once
// Output files named on the command line (--report, --image, --depth): checked before any work
// (a missing directory or a directory given as the file is a usage error), and written with every
// failure reported (a full disk, /dev/full), never silently dropped.
#include <string>

namespace zc {

// UsageError naming `flag` when `path` cannot be created: its directory is missing or not a
// directory, or the path is itself a directory. An empty path (flag not given) is fine.
void check_output_path(const std::string& path, const std::string& flag);

// The output directory `dir` (flag --out) exists or is made, and is a directory: UsageError
// otherwise. Called before anything runs.
void prepare_output_dir(const std::string& dir);

// Writes `text` to `path`; std::runtime_error naming the file and the system's reason on any
// failure, including one at flush or close.
void write_text_file(const std::string& path, const std::string& text);

} // namespace zc
