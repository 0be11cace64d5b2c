#include "trace/trace_file.hpp"

#include <fstream>

#include "trace/chrome_trace.hpp"
#include "trace/paje_trace.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

namespace zc {

void check_trace_path(const std::string& path) {
  if (!path.ends_with(".json") && !path.ends_with(".trace"))
    throw UsageError("--trace '" + path +
                     "': expected a .json (Chrome/Perfetto) or .trace (Paje) file name");
}

void write_trace(const nlohmann::json& report, const std::string& path) {
  check_trace_path(path);
  const Timeline tl = read_timeline(report, path);
  const std::string topology = report.value("topology", "cube");
  write_file_atomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    if (path.ends_with(".json"))
      out << chrome_trace(tl, topology).dump() << "\n";
    else
      write_paje_trace(tl, topology, out);
    out.close();
    if (!out) throw InputError(path, 0, "cannot write the trace");
    return true;
  });
}

} // namespace zc
