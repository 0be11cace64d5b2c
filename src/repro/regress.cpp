#include "repro/regress.hpp"
#include "repro/simulate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <regex>
#include <set>

#include "repro/json_file.hpp"
#include "repro/provenance.hpp"
#include "repro/sweep.hpp"
#include "repro/table.hpp"
#include "run/batch.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

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
    // A name, never a path: it names the report file in --write's directory.
    static const std::regex name_form(R"([A-Za-z0-9][A-Za-z0-9._+-]{0,99})");
    if (!std::regex_match(run.name, name_form) || run.name == "runs")
      throw InputError(path, 0,
                       "run name '" + run.name +
                           "': expected letters, digits, '.', '_', '+' or '-' (at most 100, not "
                           "starting with a dot or a dash, not 'runs'): it names a report file");
    for (const auto& other : runs)
      if (other.name == run.name)
        throw InputError(path, 0, "two runs are named '" + run.name + "': each needs its own name");
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
                        "virtual_time_s", "timed_s", "counters", "load_imbalance"})
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
  const auto& names = run_flag_names();
  for (const auto& [k, v] : set)
    if (std::find(names.begin(), names.end(), k) == names.end())
      throw UsageError("--set " + k + "=" + v + ": '" + k +
                       "' is not a zcube run flag (e.g. latency, bandwidth, machine, nodes)");
  std::vector<SweepPoint> points;
  for (const auto& run : runs) {
    auto flags = run.flags;
    for (const auto& [k, v] : set) // a factor (x2) scales the run's own value of a what-if
      flags[k] = find_what_if(k) && flags.count(k)
                     ? compose_what_if_text(*find_what_if(k), flags[k], v)
                     : v;
    if (flags.count("scene") && !std::filesystem::path(flags["scene"]).is_absolute())
      flags["scene"] = root + "/" + flags["scene"];
    points.push_back(make_point(std::move(flags), root + "/scenes/teapot.json"));
    if (!points.back().config) {
      std::string msg;
      for (const auto& [k, v] : set) {
        msg.append("--set ").append(k).append("=").append(v).append(": ");
      }
      msg.append("run ").append(run.name).append(": ").append(points.back().error);
      throw UsageError(msg);
    }
  }
  const auto reps = run_points(
      points, [jobs](const std::vector<RunConfig>& c) { return simulate_batch(c, jobs); });
  std::map<std::string, nlohmann::json> out;
  for (std::size_t i = 0; i < runs.size(); ++i)
    out[runs[i].name] = reduce_report(reps[i]);
  return out;
}

namespace {

// Long values (an error message, a hash) are cut so that the table stays one line a row.
std::string cell(const nlohmann::json& v) {
  if (v.is_null()) return "(none)";
  std::string s = v.is_string() ? v.get<std::string>() : v.dump();
  if (s.size() > 72) s = s.substr(0, 69) + "...";
  return s;
}

bool close_enough(const nlohmann::json& a, const nlohmann::json& b, double rtol, double atol) {
  if (a == b) return true;
  if (!a.is_number() || !b.is_number()) return false;
  const double x = a.get<double>(), y = b.get<double>();
  return std::fabs(x - y) <= std::max(atol, rtol * std::max(std::fabs(x), std::fabs(y)));
}

// Leaf by leaf; a side that lacks an object or an array is taken as empty, so every row is one
// value and never a whole sub-report.
void diff_json(const std::string& run, const std::string& path, const nlohmann::json& a,
               const nlohmann::json& b, const RegressTolerance& tol,
               std::vector<RegressDiff>& out) {
  const bool recurse = (a.is_structured() || b.is_structured()) &&
                       (a.is_null() || b.is_null() || a.type() == b.type());
  if (recurse) {
    std::set<std::string> keys;
    auto child = [](const nlohmann::json& j, const std::string& k) {
      if (j.is_object()) return j.contains(k) ? j[k] : nlohmann::json();
      if (j.is_array()) {
        const std::size_t i = std::stoul(k);
        return i < j.size() ? j[i] : nlohmann::json();
      }
      return nlohmann::json();
    };
    for (const auto* j : {&a, &b}) {
      if (j->is_object())
        for (const auto& [k, v] : j->items())
          keys.insert(k);
      if (j->is_array())
        for (std::size_t i = 0; i < j->size(); ++i)
          keys.insert(std::to_string(i));
    }
    for (const auto& k : keys)
      if (!(path.empty() && k == "provenance")) // where the report came from, not what it says
        diff_json(run, path.empty() ? k : path + "." + k, child(a, k), child(b, k), tol, out);
    return;
  }
  const QuantityKind kind = quantity_kind(path, a.is_null() ? b : a);
  if (close_enough(a, b, tol.rtol(kind), tol.atol)) return;
  RegressDiff d{run, path, cell(a), cell(b), 0, kind, tol.text(kind)};
  if (a.is_number() && b.is_number() && a.get<double>() != 0)
    d.rel = (b.get<double>() - a.get<double>()) / std::fabs(a.get<double>());
  out.push_back(d);
}

std::string status_text(const nlohmann::json& r) {
  const std::string st = r.value("status", "error");
  return r.contains("error") ? st + " (" + r["error"].get<std::string>() + ")" : st;
}

} // namespace

QuantityKind quantity_kind(const std::string& path, const nlohmann::json& value) {
  if (!value.is_number()) return QuantityKind::text;
  const std::string leaf = path.substr(path.rfind('.') + 1); // npos + 1: the whole path
  if (leaf.find("bytes") != std::string::npos) return QuantityKind::bytes;
  if (path.starts_with("phases.") || leaf.ends_with("_s") || leaf == "load_imbalance")
    return QuantityKind::time;
  return QuantityKind::count;
}

const char* kind_name(QuantityKind kind) {
  switch (kind) {
  case QuantityKind::time:
    return "time";
  case QuantityKind::count:
    return "count";
  case QuantityKind::bytes:
    return "bytes";
  case QuantityKind::text:
    break;
  }
  return "text";
}

double RegressTolerance::rtol(QuantityKind kind) const {
  switch (kind) {
  case QuantityKind::time:
    return rtol_time;
  case QuantityKind::count:
    return rtol_count;
  case QuantityKind::bytes:
    return rtol_bytes;
  case QuantityKind::text:
    break;
  }
  return 0;
}

std::string RegressTolerance::text(QuantityKind kind) const {
  if (kind == QuantityKind::text) return "exact";
  return "rtol " + num(rtol(kind), 3) + ", atol " + num(atol, 3);
}

std::vector<RegressDiff> compare_reduced(const std::map<std::string, nlohmann::json>& before,
                                         const std::map<std::string, nlohmann::json>& after,
                                         const RegressTolerance& tolerance) {
  std::vector<RegressDiff> out;
  for (const auto& [name, a] : before) {
    auto it = after.find(name);
    if (it == after.end()) {
      out.push_back({name, "(run)", "present", "missing", 0, QuantityKind::text, "exact"});
      continue;
    }
    const nlohmann::json& b = it->second;
    if (a.value("status", "error") != b.value("status", "error")) {
      out.push_back({name, "status", cell(status_text(a)), cell(status_text(b)), 0,
                     QuantityKind::text, "exact"});
      continue;
    }
    diff_json(name, "", a, b, tolerance, out);
  }
  for (const auto& [name, b] : after)
    if (!before.count(name))
      out.push_back({name, "(run)", "missing", "present", 0, QuantityKind::text, "exact"});
  return out;
}

std::vector<std::string> failed_runs(const std::map<std::string, nlohmann::json>& reduced) {
  std::vector<std::string> f;
  for (const auto& [name, r] : reduced)
    if (r.value("status", "error") == "error") f.push_back(name + ": " + r.value("error", "?"));
  return f;
}

std::map<std::string, nlohmann::json> read_report_dir(const std::string& dir) {
  if (!std::filesystem::is_directory(dir)) throw InputError(dir, 0, "not a directory of reports");
  if (access(dir.c_str(), R_OK | X_OK) != 0)
    throw InputError(dir, 0, std::string("cannot read the directory: ") + std::strerror(errno));
  std::map<std::string, nlohmann::json> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const auto p = e.path();
    if (p.extension() != ".json" || p.filename() == "runs.json") continue;
    nlohmann::json r = read_json_file(p.string(), "a report");
    // Read as a reduced report (reduce_report): an object whose status and error are text.
    if (!r.is_object() || (r.contains("status") && !r["status"].is_string()) ||
        (r.contains("error") && !r["error"].is_string()))
      throw InputError(p.string(), 0,
                       "not a reduced zcube report (expected an object with a text status)");
    out[p.stem().string()] = std::move(r);
  }
  return out;
}

void write_report_dir(const std::map<std::string, nlohmann::json>& reps, const std::string& dir) {
  prepare_output_dir(dir, "--write");
  const nlohmann::json stamp = provenance(ProvenanceFor::committed_file);
  for (const auto& [name, r] : reps) {
    nlohmann::json stamped = r;
    stamped["provenance"] = stamp;
    write_text(dir + "/" + name + ".json", stamped.dump(1) + "\n");
  }
}

nlohmann::json check_report_schema(const std::map<std::string, nlohmann::json>& reps,
                                   const std::string& flag, const std::string& dir,
                                   bool allow_other_schema) {
  nlohmann::json found;
  for (const auto& [name, r] : reps) {
    const int schema = schema_version_of(r);
    if (schema != kSchemaVersion && !allow_other_schema)
      throw UsageError(flag + " " + dir + ": " + name + ".json has schema " +
                       std::to_string(schema) +
                       (schema == 0 ? " (no provenance: written before zcube recorded one)" : "") +
                       ", this zcube's is " + std::to_string(kSchemaVersion) +
                       ": rewrite it with zcube regress --write, or compare anyway with "
                       "--allow-schema");
    if (found.is_null() && r.contains("provenance")) found = r["provenance"];
  }
  return found;
}

} // namespace zc
