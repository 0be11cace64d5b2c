#pragma once
// Output files named on the command line (--report, --image, --depth): checked before any work
// (a missing directory, a directory given as the file, two outputs of one run on the same file
// are usage errors), and written atomically: to a temporary file beside the target, renamed into
// place once complete, so that a failed write leaves no partial file and two runs writing the
// same file leave one whole file, never a mix. Every failure is reported (a full disk, /dev/full).
#include <functional>
#include <string>
#include <vector>

namespace zc {

// UsageError naming `flag` when `path` cannot be created: its directory is missing, not a
// directory or not writable, or the path is itself a directory, a FIFO or a socket (writing would
// wait for a reader), or "-" (standard output: util/stdout_result.hpp). An empty path (flag not
// given) is fine.
void check_output_path(const std::string& path, const std::string& flag);

// check_output_path for each (flag, path) given, and no two of them naming the same file.
void check_output_paths(const std::vector<std::pair<std::string, std::string>>& flag_paths);

// UsageError naming `flag` unless `path` (when given) names an image format zcube writes by its
// extension: .png, .exr, .tif, .tiff, .jpg, .jpeg, .bmp, .ppm, .pnm, .tga, .hdr.
void check_image_path(const std::string& path, const std::string& flag);

// The output directory `dir` (given by `flag`) exists or is made, is a directory and takes new
// files: UsageError otherwise. Called before anything runs.
void prepare_output_dir(const std::string& dir, const std::string& flag = "--out");

// Calls `produce(tmp)` to write the whole file at `tmp`, a temporary path beside `path` with the
// same extension (image and plot writers choose the format by it), then renames it to `path`. When
// `produce` throws or returns false, the temporary file is removed and std::runtime_error names
// `path`. A device or a pipe this process was given (/dev/null, /dev/stdout) is produced in a
// temporary directory and copied to it, every write checked; a FIFO or a socket is refused.
void write_file_atomically(const std::string& path,
                           const std::function<bool(const std::string& tmp)>& produce);

// Writes `text` to `path` atomically; std::runtime_error naming the file and the system's reason
// on any failure, including one at flush or close.
void write_text_file(const std::string& path, const std::string& text);

} // namespace zc
