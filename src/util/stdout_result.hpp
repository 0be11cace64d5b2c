#pragma once
// An output flag given "-" (or /dev/stdout): the file is the command's result on standard output,
// so that `zcube run ... --report - | python3 -m json.tool` works. Everything else the command
// prints (its summary, SimGrid's and the plot scripts' lines) then goes to standard error.
#include <string>

namespace zc {

// "-", /dev/stdout, /dev/fd/1 or /proc/self/fd/1.
bool names_stdout(const std::string& path);

// Keeps the process's standard output for the result alone: descriptor 1 (std::cout, C stdio and
// child processes) is made a copy of standard error from now on. Called once, before anything is
// printed; a second call does nothing.
void reserve_stdout_for_result();

// Writes `text` to the standard output reserve_stdout_for_result() kept (or to standard output
// if it was not called), every write checked: std::runtime_error on a failure (a full disk, a
// closed pipe).
void write_result_to_stdout(const std::string& text);

// write_result_to_stdout when `path` names_stdout, else write_text_file(path, text).
void write_result_file(const std::string& path, const std::string& text);

} // namespace zc
