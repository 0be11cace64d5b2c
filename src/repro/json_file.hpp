#pragma once
// A JSON file read whole, or an InputError naming the file and the reason (`what` says what the
// file was meant to be: "the report", "the runs file").
#include <string>

#include <nlohmann/json.hpp>

namespace zc {

nlohmann::json read_json_file(const std::string& path, const std::string& what);

} // namespace zc
