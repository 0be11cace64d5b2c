#include "repro/regress.hpp"

#include <cmath>
#include <filesystem>
#include <set>

#include "repro/json_file.hpp"
#include "repro/sweep.hpp"
#include "repro/table.hpp"
#include "sim/batch.hpp"
#include "util/error.hpp"

namespace zc {

std::vector<RegressRun> read_regress_runs(const std::string& path) {
  const nlohmann::json j = read_json_file(path, "the runs file");
  if (!j.contains("runs") || !j["runs"].is_array())
    throw InputError(path, 0, "expected {\"runs\": [...]}");
  std::vector<RegressRun> runs;
  for (const auto& r : j["runs"]) {
    if (!r.is_object() || !r.contains("name") || !r["name"].is_string())
      throw InputError(path, 0, "every run needs a \"name\"");
    RegressRun run{r["name"], {}};
    for (const auto& [k, v] : r.items()) {
      if (k == "name") continue;
      const auto& fl = run_flag_names();
      if (std::find(fl.begin(), fl.end(), k) == fl.end() || !v.is_string())
        throw InputError(
            path, 0, "run " + run.name + ": '" + k + "' is not a zcube run flag given as a string");
      run.flags[k] = v.get<std::string>();
    }
    runs.push_back(run);
  }
  return runs;
}

nlohmann::json reduce_report(const nlohmann::json& r) {
  nlohmann::json o = {{"status", r.value("status", "error")}};
  if (r.contains("error")) o["error"] = r["error"];
  for (const char* k : {"machine", "nodes", "topology", "fidelity", "algorithm", "frames",
                        "virtual_time_s", "counters", "load_imbalance"})
    if (r.contains(k)) o[k] = r[k];
  if (r.contains("phases")) {
    o["phases"] = nlohmann::json::object();
    for (const auto& p : r["phases"])
      o["phases"][p["name"].get<std::string>()] = p["max_s"];
  }
  if (r.contains("communication")) o["communication"] = r["communication"];
  if (r.contains("image")) o["image"] = r["image"];
  if (r.contains("per_node")) {
    double peak = 0;
    for (const auto& n : r["per_node"])
      peak = std::max(peak, n.value("peak_memory_bytes", 0.0));
    o["peak_memory_bytes"] = peak;
  }
  return o;
}

std::map<std::string, nlohmann::json> run_regress(const std::vector<RegressRun>& runs,
                                                  const std::string& root, int jobs,
                                                  const std::map<std::string, std::string>& set) {
  std::vector<SweepPoint> points;
  for (const auto& run : runs) {
    auto flags = run.flags;
    for (const auto& [k, v] : set)
      flags[k] = v;
    if (flags.count("scene") && !std::filesystem::path(flags["scene"]).is_absolute())
      flags["scene"] = root + "/" + flags["scene"];
    points.push_back(make_point(std::move(flags), root + "/scenes/teapot.json"));
  }
  const auto reps =
      run_points(points, [jobs](const std::vector<SimConfig>& c) { return run_batch(c, jobs); });
  std::map<std::string, nlohmann::json> out;
  for (std::size_t i = 0; i < runs.size(); ++i)
    out[runs[i].name] = reduce_report(reps[i]);
  return out;
}

namespace {

void diff_json(const std::string& run, const std::string& path, const nlohmann::json& a,
               const nlohmann::json& b, std::vector<RegressDiff>& out) {
  if (a.is_object() && b.is_object()) {
    std::set<std::string> keys;
    for (const auto& [k, v] : a.items())
      keys.insert(k);
    for (const auto& [k, v] : b.items())
      keys.insert(k);
    for (const auto& k : keys)
      diff_json(run, path.empty() ? k : path + "." + k, a.contains(k) ? a[k] : nlohmann::json(),
                b.contains(k) ? b[k] : nlohmann::json(), out);
    return;
  }
  if (a == b) return;
  RegressDiff d{run, path, a.is_null() ? "(none)" : a.dump(), b.is_null() ? "(none)" : b.dump(), 0};
  if (a.is_number() && b.is_number() && a.get<double>() != 0)
    d.rel = (b.get<double>() - a.get<double>()) / std::fabs(a.get<double>());
  out.push_back(d);
}

} // namespace

std::vector<RegressDiff> compare_reduced(const std::map<std::string, nlohmann::json>& before,
                                         const std::map<std::string, nlohmann::json>& after) {
  std::vector<RegressDiff> out;
  for (const auto& [name, a] : before) {
    auto it = after.find(name);
    if (it == after.end()) {
      out.push_back({name, "(run)", "present", "missing", 0});
      continue;
    }
    diff_json(name, "", a, it->second, out);
  }
  for (const auto& [name, b] : after)
    if (!before.count(name)) out.push_back({name, "(run)", "missing", "present", 0});
  return out;
}

std::map<std::string, nlohmann::json> read_report_dir(const std::string& dir) {
  if (!std::filesystem::is_directory(dir)) throw InputError(dir, 0, "not a directory of reports");
  std::map<std::string, nlohmann::json> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const auto p = e.path();
    if (p.extension() != ".json" || p.filename() == "runs.json") continue;
    out[p.stem().string()] = read_json_file(p.string(), "a report");
  }
  return out;
}

void write_report_dir(const std::map<std::string, nlohmann::json>& reps, const std::string& dir) {
  std::filesystem::create_directories(dir);
  for (const auto& [name, r] : reps)
    write_text(dir + "/" + name + ".json", r.dump(1) + "\n");
}

} // namespace zc
