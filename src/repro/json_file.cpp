#include "repro/json_file.hpp"

#include <fstream>

#include "util/error.hpp"
#include "util/input_file.hpp"

namespace zc {

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  check_input_file(path);
  std::ifstream f(path);
  if (!f) throw InputError(path, 0, "cannot open " + what);
  try {
    return nlohmann::json::parse(f);
  } catch (const nlohmann::json::parse_error& ex) {
    throw InputError(path, 0, what + " is not JSON: " + ex.what());
  }
}

} // namespace zc
