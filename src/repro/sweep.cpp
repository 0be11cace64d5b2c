#include "repro/sweep.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>

#include "algo/algorithm.hpp"
#include "repro/provenance.hpp"
#include "repro/reproduce.hpp"
#include "repro/table.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

namespace zc {

std::vector<std::string> split_list(const std::string& text, const std::string& flag) {
  std::vector<std::string> v;
  std::size_t a = 0;
  while (true) {
    const std::size_t b = text.find(',', a);
    const std::string item = text.substr(a, b == std::string::npos ? std::string::npos : b - a);
    if (item.empty()) throw UsageError("--" + flag + " '" + text + "': empty item in the list");
    v.push_back(item);
    if (b == std::string::npos) break;
    a = b + 1;
  }
  return v;
}

std::vector<SweepPoint> expand_sweep(const std::vector<SweepAxis>& axes, const std::string& scene,
                                     const Locate& locate) {
  std::vector<SweepPoint> pts(1);
  for (const auto& ax : axes) {
    std::vector<SweepPoint> next;
    for (const auto& p : pts)
      for (const auto& val : ax.values) {
        SweepPoint q = p;
        q.values[ax.flag] = val;
        next.push_back(q);
      }
    pts = std::move(next);
  }
  for (auto& p : pts)
    p = make_point(std::move(p.values), scene, locate);
  return pts;
}

SweepPoint make_point(std::map<std::string, std::string> values, const std::string& scene,
                      const Locate& locate) {
  SweepPoint p;
  p.values = std::move(values);
  auto flags = p.values; // the files found where they are; the row keeps the text given
  if (locate)
    for (const char* f : {"scene", "machine"})
      if (flags.count(f) && !flags[f].empty()) flags[f] = locate(flags[f]);
  std::erase_if(flags, [](const auto& kv) { return kv.second.empty(); }); // "": not given
  try {
    p.config = config_from_flags(flags, locate ? locate(scene) : scene);
  } catch (const std::exception& ex) {
    p.error = ex.what();
  }
  return p;
}

std::vector<nlohmann::json> run_points(const std::vector<SweepPoint>& points,
                                       const BatchRunner& runner) {
  std::vector<RunConfig> cfgs;
  for (const auto& p : points)
    if (p.config) cfgs.push_back(*p.config);
  const auto ran = runner(cfgs);
  if (ran.size() != cfgs.size()) return {};
  std::vector<nlohmann::json> reports;
  std::size_t k = 0;
  for (const auto& p : points)
    reports.push_back(p.config ? ran[k++]
                               : nlohmann::json{{"status", "invalid"}, {"error", p.error}});
  return reports;
}

namespace {

// An integer-valued flag's text as a number ("16" -> 16), else the text.
nlohmann::json typed(const std::string& text) {
  std::size_t used = 0;
  try {
    const long long v = std::stoll(text, &used);
    if (used == text.size() && !text.empty() && text.find_first_of("+ ") == std::string::npos)
      return v;
  } catch (const std::exception&) {
  }
  return text;
}

} // namespace

void add_axis_columns(nlohmann::json& row, const std::string& flag, const std::string& text) {
  const WhatIfSpec* w = find_what_if(flag);
  if (!w) {
    row[flag] = typed(text);
    return;
  }
  row[flag] = text; // as given; its numeric twins beside it (SI units, or the factor)
  std::optional<WhatIfValue> v;
  try {
    if (!text.empty()) v = parse_what_if(*w, text);
  } catch (const std::exception&) { // the point is invalid and says why
  }
  row[w->key] = v && !v->relative ? nlohmann::json(v->value) : nlohmann::json(nullptr);
  if (w->quantity != WhatIfSpec::Quantity::Factor)
    row[w->factor_key()] = v && v->relative ? nlohmann::json(v->value) : nlohmann::json(nullptr);
}

nlohmann::json sweep_rows(const std::vector<SweepAxis>& axes, const std::vector<SweepPoint>& pts,
                          const std::vector<nlohmann::json>& reps) {
  std::vector<std::string> phases;
  for (const auto& r : reps)
    if (r.contains("phases"))
      for (const auto& p : r["phases"])
        if (std::find(phases.begin(), phases.end(), p["name"]) == phases.end())
          phases.push_back(p["name"]);
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const nlohmann::json& r = reps[i];
    nlohmann::json row = nlohmann::json::object();
    row["index"] = i;
    for (const auto& ax : axes)
      add_axis_columns(row, ax.flag, pts[i].values.at(ax.flag));
    const std::string status = r.value("status", "error");
    row["status"] = status;
    row["error"] = r.value("error", "");
    const bool ran = status == "ok";
    row["virtual_s"] = ran ? nlohmann::json(r["virtual_time_s"]) : nlohmann::json(nullptr);
    // The paper's timed region (elastic's per-picture loop, Kurc's Table 2 columns), else the
    // whole run (Blazek): what speed-ups divide (docs/papers.md).
    row["timed_s"] = ran ? nlohmann::json(timed_s(r)) : nlohmann::json(nullptr);
    row["wall_s"] = r.contains("host") ? r["host"]["wall_time_s"] : nlohmann::json(nullptr);
    const auto comm = r.value("communication", nlohmann::json::object());
    row["messages"] = ran ? comm.value("messages", nlohmann::json(nullptr)) : nullptr;
    row["bytes"] = ran ? comm.value("bytes", nlohmann::json(nullptr)) : nullptr;
    row["concurrent_volume_bytes"] =
        ran ? comm.value("concurrent_volume_bytes", nlohmann::json(nullptr)) : nullptr;
    row["load_imbalance"] = ran ? r.value("load_imbalance", nlohmann::json(nullptr)) : nullptr;
    const auto img = r.value("image", nlohmann::json::object());
    row["image_sha256"] = img.value("sha256", nlohmann::json(nullptr));
    row["identical"] = img.value("identical_to_sequential", nlohmann::json(nullptr));
    for (const auto& ph : phases) {
      nlohmann::json v = nullptr;
      if (ran)
        for (const auto& p : r["phases"])
          if (p["name"] == ph) v = p["max_s"];
      row["phase:" + ph] = v;
    }
    rows.push_back(row);
  }
  return rows;
}

namespace {

// The flags some algorithm declares as its own option (--vertices, --timed, --packet, ...): they
// choose the parallel program, not the machine or the scene, so a baseline (the sequential run on
// one node) shares every other flag with the points it serves.
bool algorithm_option(const std::string& flag) {
  for (const auto& a : algorithms())
    for (const auto& o : a.options)
      if (o.name == flag) return true;
  return false;
}

bool algorithm_axis(const std::string& flag) {
  return flag == "algorithm" || flag == "nodes" || algorithm_option(flag);
}

std::string value_of(const SweepPoint& p, const char* flag, const char* def) {
  auto it = p.values.find(flag);
  return it == p.values.end() || it->second.empty() ? def : it->second;
}

// The one-node run the point's paper divides by (Algorithm::reference, docs/papers.md); an
// unknown algorithm (an invalid point, which never runs) gets sequential.
std::string reference_of(const SweepPoint& p) {
  const std::string name = value_of(p, "algorithm", "sequential");
  for (const auto& a : algorithms())
    if (a.name == name) return a.reference;
  return "sequential";
}

// Where the reference is stored in a baseline key: no flag has an empty name.
const std::string kReferenceKey;

// The values of the axes that must match between a point and its baseline, and the reference.
std::map<std::string, std::string> baseline_key(const SweepPoint& p) {
  std::map<std::string, std::string> k;
  for (const auto& [f, v] : p.values)
    if (!algorithm_axis(f)) k[f] = v;
  k[kReferenceKey] = reference_of(p);
  return k;
}

// sequential and scanline render on node 0 alone; Blazek's node-initiated uses every node.
bool renders_on_node0_alone(const std::string& algorithm) {
  return algorithm == "sequential" || algorithm == "scanline";
}

bool on_platform_file(const std::map<std::string, std::string>& values) {
  const auto m = values.find("machine");
  return m != values.end() && is_platform_file(m->second);
}

// A platform file states its node count: there the point runs on one node only if its algorithm
// renders on node 0 alone.
bool runs_on_one_node(const SweepPoint& p) {
  return value_of(p, "nodes", "1") == "1" &&
         (!on_platform_file(p.values) ||
          renders_on_node0_alone(value_of(p, "algorithm", "sequential")));
}

} // namespace

bool is_baseline(const SweepPoint& p) {
  bool options = false;
  for (const auto& [f, v] : p.values)
    options = options || (algorithm_option(f) && !v.empty());
  // A baseline point that cannot run (no configuration) still stands for its key: its rows get
  // no speed-up rather than another run's.
  return value_of(p, "algorithm", "sequential") == reference_of(p) && !options &&
         (runs_on_one_node(p) || !p.config);
}

void add_baselines(const std::vector<SweepAxis>& axes, std::vector<SweepPoint>& points,
                   const std::string& scene, const Locate& locate) {
  std::vector<std::map<std::string, std::string>> have, want;
  for (const auto& p : points) {
    auto& list = is_baseline(p) ? have : want;
    if (std::find(list.begin(), list.end(), baseline_key(p)) == list.end())
      list.push_back(baseline_key(p));
  }
  for (const auto& k : want) {
    if (std::find(have.begin(), have.end(), k) != have.end()) continue;
    auto flags = k;
    flags.erase(kReferenceKey);
    const std::string ref = k.at(kReferenceKey);
    flags["algorithm"] = ref;
    // A platform file states its node count; sequential and scanline render on node 0 alone, so
    // on the file's P nodes they take their one-node time. node-initiated would use all P.
    const bool file = on_platform_file(k);
    if (!file) flags["nodes"] = "1";
    SweepPoint p = make_point(flags, scene, locate);
    if (file && !renders_on_node0_alone(ref)) {
      p.config.reset();
      // Appended piecewise: GCC 12 at -O3 reports a false -Wrestrict on the chained operator+.
      p.error = "--machine ";
      p.error.append(k.at("machine")).append(": the reference ").append(ref);
      p.error.append(" on one node cannot run on a platform file (it states its node count)");
    }
    for (const auto& ax : axes)
      if (!p.values.count(ax.flag)) p.values[ax.flag] = "";
    points.push_back(std::move(p));
  }
}

bool add_speedups(const std::vector<SweepPoint>& points, const std::vector<nlohmann::json>& reports,
                  nlohmann::json& rows) {
  bool any = false;
  for (const auto& p : points)
    any = any || is_baseline(p);
  if (!any) return false;
  // The time each paper's speed-up divides, as zcube reproduce takes it (timed_s in
  // repro/reproduce.hpp); none for a point that did not run to the end.
  const auto paper_time = [&](std::size_t i) {
    return i < reports.size() && ok(reports[i]) ? std::optional<double>(timed_s(reports[i]))
                                                : std::nullopt;
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    nlohmann::json& row = rows[i];
    row["speedup"] = nullptr;
    row["efficiency"] = nullptr;
    const auto t = paper_time(i);
    if (!t) continue;
    for (std::size_t b = 0; b < points.size(); ++b) {
      if (!is_baseline(points[b]) || baseline_key(points[b]) != baseline_key(points[i])) continue;
      const auto base = paper_time(b);
      if (!base) continue;
      const double sp = *base / *t;
      const int nodes = is_baseline(points[i]) ? 1 : reports[i].value("nodes", 1);
      row["speedup"] = sp;
      row["efficiency"] = sp / std::max(1, nodes);
      break;
    }
  }
  return true;
}

const std::vector<std::string>& sweep_value_columns() {
  static const std::vector<std::string> c = {
      "virtual_s",     "timed_s",  "speedup", "efficiency",
      "wall_s",        "messages", "bytes",   "concurrent_volume_bytes",
      "load_imbalance"};
  return c;
}

void prepare_sweep_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  prepare_output_dir(dir);
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().stem() == "sweep") fs::remove(e.path(), ec);
}

void write_sweep(const std::vector<SweepAxis>& axes, const nlohmann::json& rows,
                 const std::vector<nlohmann::json>& reps, const std::string& dir) {
  std::filesystem::create_directories(dir);
  Table t;
  if (!rows.empty())
    for (const auto& [k, v] : rows[0].items())
      t.header.push_back(k);
  // nlohmann::json objects sort their keys; put index and the axes first, as given.
  std::vector<std::string> order = {"index"};
  for (const auto& ax : axes) {
    order.push_back(ax.flag);
    if (const WhatIfSpec* w = find_what_if(ax.flag)) {
      order.push_back(w->key);
      if (w->quantity != WhatIfSpec::Quantity::Factor) order.push_back(w->factor_key());
    }
  }
  for (const char* k :
       {"status", "virtual_s", "timed_s", "speedup", "efficiency", "wall_s", "messages", "bytes",
        "concurrent_volume_bytes", "load_imbalance", "identical", "image_sha256"})
    if (std::find(t.header.begin(), t.header.end(), k) != t.header.end()) order.push_back(k);
  for (const auto& h : t.header)
    if (std::find(order.begin(), order.end(), h) == order.end() && h != "error") order.push_back(h);
  order.push_back("error");
  t.header = order;
  for (const auto& row : rows) {
    std::vector<std::string> cells;
    for (const auto& h : order) {
      const auto& v = row.contains(h) ? row[h] : nlohmann::json(nullptr);
      cells.push_back(v.is_null()           ? ""
                      : v.is_string()       ? v.get<std::string>()
                      : v.is_number_float() ? num(v.get<double>(), 10)
                                            : v.dump());
    }
    t.add(cells);
  }
  t.write_csv(dir + "/sweep.csv");
  nlohmann::json axes_j = nlohmann::json::array();
  for (const auto& ax : axes)
    axes_j.push_back({{"flag", ax.flag}, {"values", ax.values}});
  const nlohmann::json doc = {
      {"provenance", provenance()}, {"axes", axes_j}, {"rows", rows}, {"reports", reps}};
  write_text(dir + "/sweep.json", doc.dump(1) + "\n");
}

} // namespace zc
