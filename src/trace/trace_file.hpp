#pragma once
// `zcube run --trace FILE`: the format from the extension (.json Chrome/Perfetto, .trace Paje).
#include <string>

#include <nlohmann/json.hpp>

namespace zc {

// UsageError (before any simulation) unless the extension names a trace format.
void check_trace_path(const std::string& path);
// Writes the traced report's timeline to `path`; InputError when it cannot be written.
void write_trace(const nlohmann::json& report, const std::string& path);

} // namespace zc
