#include "repro/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "machine/units.hpp"
#include "repro/table.hpp"
#include "util/error.hpp"
#include "util/image_size.hpp"

namespace zc {

const std::vector<std::string>& sweep_flags() {
  static const std::vector<std::string> f = {
      "machine",  "nodes",   "topology",  "fidelity", "algorithm", "scene",  "size",
      "frames",   "latency", "bandwidth", "per-hop",  "cpu-scale", "memory", "cost-scale",
      "vertices", "output",  "packet",    "lines",    "forward"};
  return f;
}

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

namespace {

int parse_int(const std::string& s, const std::string& flag) {
  std::size_t used = 0;
  int v = 0;
  try {
    v = std::stoi(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || s.empty())
    throw UsageError("--" + flag + " '" + s + "': expected an integer");
  return v;
}

double parse_positive(const std::string& s, const std::string& flag) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end || !(v > 0) || !std::isfinite(v))
    throw UsageError("--" + flag + " '" + s + "': expected a positive number");
  return v;
}

} // namespace

SimConfig sweep_config(const std::map<std::string, std::string>& v, const std::string& scene) {
  auto get = [&](const char* k, const char* def) {
    auto it = v.find(k);
    return it == v.end() ? std::string(def) : it->second;
  };
  SimConfig c;
  c.machine = get("machine", "ipsc2");
  c.topology = parse_topology(get("topology", "cube"));
  c.fidelity = parse_fidelity(get("fidelity", "circuit"));
  const bool xml = c.machine.ends_with(".xml");
  c.nodes = v.count("nodes") ? parse_int(v.at("nodes"), "nodes") : (xml ? 0 : 1);
  if (!xml) check_node_count(c.topology, c.nodes);
  c.algorithm = get("algorithm", "sequential");
  c.scene_path = get("scene", scene.c_str());
  if (v.count("size")) {
    const ImageSize s = parse_image_size(v.at("size"));
    c.width = s.width;
    c.height = s.height;
  }
  c.options.frames = v.count("frames") ? parse_int(v.at("frames"), "frames") : 1;
  if (v.count("latency")) c.overrides.latency_s = parse_time(v.at("latency"), "--latency");
  if (v.count("bandwidth"))
    c.overrides.bandwidth_Bps = parse_bandwidth(v.at("bandwidth"), "--bandwidth");
  if (v.count("per-hop")) c.overrides.per_hop_s = parse_time(v.at("per-hop"), "--per-hop");
  if (v.count("cpu-scale")) c.overrides.cpu_scale = parse_positive(v.at("cpu-scale"), "cpu-scale");
  if (v.count("memory")) c.overrides.memory_bytes = parse_bytes(v.at("memory"), "--memory");
  if (v.count("cost-scale"))
    c.overrides.cost_scale = parse_positive(v.at("cost-scale"), "cost-scale");
  for (const char* k : {"vertices", "output", "packet", "lines", "forward"})
    if (v.count(k)) c.options.values[k] = v.at(k);
  // The algorithm and its options are checked here, so a bad combination fails only its point.
  const Algorithm& a = find_algorithm(c.algorithm);
  for (const auto& [k, val] : c.options.values)
    if (std::find(a.option_keys.begin(), a.option_keys.end(), k) == a.option_keys.end())
      throw UsageError("--" + k + " does not apply to algorithm " + a.name);
  return c;
}

std::vector<SweepPoint> expand_sweep(const std::vector<SweepAxis>& axes, const std::string& scene) {
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
  for (auto& p : pts) {
    try {
      p.config = sweep_config(p.values, scene);
    } catch (const std::exception& ex) {
      p.error = ex.what();
    }
  }
  return pts;
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
      row[ax.flag] = pts[i].values.at(ax.flag);
    const std::string status = pts[i].config ? r.value("status", "error") : "error";
    row["status"] = status;
    row["error"] = pts[i].config ? r.value("error", "") : pts[i].error;
    const bool ran = status == "ok";
    row["virtual_s"] = ran ? nlohmann::json(r["virtual_time_s"]) : nlohmann::json(nullptr);
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

void write_sweep(const std::vector<SweepAxis>& axes, const nlohmann::json& rows,
                 const std::vector<nlohmann::json>& reps, const std::string& dir) {
  std::filesystem::create_directories(dir);
  Table t;
  if (!rows.empty())
    for (const auto& [k, v] : rows[0].items())
      t.header.push_back(k);
  // nlohmann::json objects sort their keys; put index and the axes first, as given.
  std::vector<std::string> order = {"index"};
  for (const auto& ax : axes)
    order.push_back(ax.flag);
  for (const char* k : {"status", "virtual_s", "wall_s", "messages", "bytes",
                        "concurrent_volume_bytes", "load_imbalance", "identical", "image_sha256"})
    order.push_back(k);
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
  write_text(dir + "/sweep.json",
             nlohmann::json{{"axes", axes_j}, {"rows", rows}, {"reports", reps}}.dump(1) + "\n");
}

} // namespace zc
