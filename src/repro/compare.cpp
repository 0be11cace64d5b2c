#include "repro/compare.hpp"

#include <map>

#include "repro/json_file.hpp"
#include "util/error.hpp"

namespace zc {

nlohmann::json read_report(const std::string& path) {
  const nlohmann::json j = read_json_file(path, "the report");
  if (!j.is_object() || !j.contains("virtual_time_s") || !j["virtual_time_s"].is_number() ||
      !j.contains("phases") || !j["phases"].is_array())
    throw InputError(path, 0, "not a zcube report (no virtual_time_s or phases)");
  for (const auto& p : j["phases"])
    if (!p.is_object() || !p.contains("name") || !p["name"].is_string() || !p.contains("max_s") ||
        !p["max_s"].is_number())
      throw InputError(path, 0, "not a zcube report (a phase without name or max_s)");
  return j;
}

Table compare_reports(const nlohmann::json& m, const nlohmann::json& p) {
  if (m.value("algorithm", "") != p.value("algorithm", ""))
    throw UsageError("compare: the reports are of different algorithms (" +
                     m.value("algorithm", "?") + ", " + p.value("algorithm", "?") + ")");
  if (m.value("nodes", 0) != p.value("nodes", 0))
    throw UsageError("compare: the reports are of different node counts (" +
                     std::to_string(m.value("nodes", 0)) + ", " +
                     std::to_string(p.value("nodes", 0)) + ")");
  std::vector<std::string> order;
  std::map<std::string, double> mt, pt;
  for (const auto& x : m["phases"]) {
    order.push_back(x["name"]);
    mt[x["name"]] = x["max_s"];
  }
  for (const auto& x : p["phases"]) {
    if (!mt.count(x["name"])) order.push_back(x["name"]);
    pt[x["name"]] = x["max_s"];
  }
  Table t{{"phase", "measured_s", "predicted_s", "rel_error"}, {}};
  auto row = [&](const std::string& name, const double* a, const double* b) {
    t.add({name, a ? num(*a, 4) : "", b ? num(*b, 4) : "",
           a && b && *a > 0 ? percent((*b - *a) / *a) : ""});
  };
  for (const auto& n : order)
    row(n, mt.count(n) ? &mt[n] : nullptr, pt.count(n) ? &pt[n] : nullptr);
  const double a = m["virtual_time_s"], b = p["virtual_time_s"];
  row("total", &a, &b);
  // The paper's timed region (docs/papers.md), what speed-ups divide, when both runs mark one.
  if (m.contains("timed_s") && p.contains("timed_s") && m["timed_s"].is_number() &&
      p["timed_s"].is_number()) {
    const double ta = m["timed_s"], tb = p["timed_s"];
    row("timed", &ta, &tb);
  }
  return t;
}

} // namespace zc
