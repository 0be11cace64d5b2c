#pragma once
// A built-in machine as data: the text of machines/<name>.json read into a MachineSpec, each figure
// a {"value", "source"} pair (docs/adding-a-machine.md). The file is checked as it is read: a
// missing, unknown or ill-typed field is an InputError naming the file and the field.
#include <string>
#include <vector>

#include "machine/machine.hpp"

namespace zc {

// The machine `text` describes; `path` names the file in errors and must end in "<name>.json".
// `cpus` are the CPU models it may name; the cost table is left to the caller (the CPU's).
MachineSpec parse_machine_file(const std::string& path, const std::string& text,
                               const std::vector<std::string>& cpus);

} // namespace zc
