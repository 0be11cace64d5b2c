// The error of the network fidelities: a fixed set of runs under the three (analytic, flow,
// circuit). The circuit model (channels held in dimension order for the whole message, as the
// Direct-Connect Module does) is the reference; the others trade accuracy under contention for
// speed.
#include "repro/reproduce.hpp"
#include "repro/table.hpp"

namespace zc {

namespace {

struct FidelityRun {
  std::string name, machine, topology, algorithm, scene, option_key, option_value;
  int nodes, size;
  double memory_mib; // 0: the machine's
};
const std::vector<FidelityRun> kRuns = {
    {"elastic-teapot-ipsc860-16", "ipsc860", "cube", "elastic", "scenes/teapot.json", "", "", 16,
     256, 0},
    {"elastic-teapot-volvox-ring-16", "volvox", "ring", "elastic", "scenes/teapot.json", "", "", 16,
     256, 0},
    {"pair-rs-1pot-ipsc2-16", "ipsc2", "cube", "pair-rs", "scenes/kurc/1pot.json", "", "", 16, 400,
     0},
    {"aapc-hbp-2pot-ipsc2-16", "ipsc2", "cube", "aapc-hbp", "scenes/kurc/2pot.json", "", "", 16,
     400, 0},
    {"zbuf-exc-1pot-ipsc2-16", "ipsc2", "cube", "zbuf-exc", "scenes/kurc/1pot.json", "", "", 16,
     400, 0},
    {"node-initiated-16-spheres-ipsc2-16", "ipsc2", "cube", "node-initiated",
     "scenes/blazek/thesis_spheres_16.json", "", "", 16, 512, 16},
    {"object-forwarding-4-spheres-ipsc2-16", "ipsc2", "cube", "object-forwarding",
     "scenes/blazek/thesis_spheres_4.json", "forward", "object", 16, 512, 16},
    // Beyond the papers' machines: all-to-all heavy merging and the elastic z-buffer on
    // 128 nodes, pairwise merging on 1024, where contention and the simulators' costs differ.
    {"aapc-hbp-1pot-ipsc2-128", "ipsc2", "cube", "aapc-hbp", "scenes/kurc/1pot.json", "", "", 128,
     400, 0},
    {"zbuf-exc-1pot-ipsc2-128", "ipsc2", "cube", "zbuf-exc", "scenes/kurc/1pot.json", "", "", 128,
     400, 0},
    {"elastic-teapot-ipsc860-128", "ipsc860", "cube", "elastic", "scenes/teapot.json", "", "", 128,
     256, 0},
    {"pair-rs-1pot-ipsc2-1024", "ipsc2", "cube", "pair-rs", "scenes/kurc/1pot.json", "", "", 1024,
     400, 0},
};
const char* const kFidelities[] = {"analytic", "flow", "circuit"};

std::string key(const FidelityRun& r, const char* f) {
  return r.name + "/" + f;
}

// The error against the seeds' figure for the run's network-bound phase (Kurc Table 2's pixel
// merging), else its first figure; "" where the seeds print none (repro/paper_figures).
std::string paper_error(const nlohmann::json& rep) {
  if (!rep.contains("paper")) return "";
  const nlohmann::json* pick = nullptr;
  for (const auto& f : rep["paper"])
    if (f.contains("rel_error") && (!pick || f.value("phase", "") == "pixel_merging")) pick = &f;
  return pick ? num((*pick)["rel_error"].get<double>(), 4) : "";
}

// What each run cost the simulator, in its own events (the report's simulation_cost, the same in
// every run; run/sim_cost.hpp): the messages the algorithm sent, the transfers SimGrid's bandwidth
// sharing solved (flow), zcube's own network events (circuit), SimGrid's time steps and the
// actors' switches to SimGrid and back. The host seconds they take are measured apart, by
// bench/fidelity_cost.py (results/fidelity_cost.csv).
const char* const kCostColumns[] = {"flows", "network_events", "time_steps", "actor_switches"};

std::vector<std::string> cost_cells(const nlohmann::json& rep) {
  std::vector<std::string> cells = {
      std::to_string(rep.at("communication").at("messages").get<std::uint64_t>())};
  const nlohmann::json& c = rep.at("simulation_cost");
  for (const char* k : kCostColumns)
    cells.push_back(std::to_string(c.at(k).get<std::uint64_t>()));
  return cells;
}

// fidelity.csv holds the deterministic outputs only; the host's wall time of each run goes to
// host_cost.csv, which is not committed (it varies from run to run and machine to machine).
std::string write_fidelity(const Reports& reps, const std::string& dir) {
  // virtual_s is the whole run, timed_s the paper's timed region; rel_error is timed_s's against
  // the circuit model's (the region the papers' figures time).
  Table t{{"run", "algorithm", "fidelity", "nodes", "status", "virtual_s", "timed_s", "rel_error",
           "paper_rel_error", "messages"},
          {}};
  for (const char* k : kCostColumns)
    t.header.push_back(k);
  Table host{{"run", "algorithm", "fidelity", "nodes", "wall_s", "peak_rss_bytes"}, {}};
  for (const auto& r : kRuns) {
    const auto& ref = reps.at(key(r, "circuit"));
    for (const char* f : kFidelities) {
      const auto& rep = reps.at(key(r, f));
      if (!ok(rep) || !ok(ref)) {
        std::vector<std::string> row = {r.name, r.algorithm, f, std::to_string(r.nodes),
                                        status_of(ok(rep) ? ref : rep)};
        row.resize(t.header.size());
        t.add(row);
        continue;
      }
      const double v = timed_s(rep), e = (v - timed_s(ref)) / timed_s(ref);
      std::vector<std::string> row = {r.name,
                                      r.algorithm,
                                      f,
                                      std::to_string(r.nodes),
                                      "ok",
                                      num(whole_run_s(rep)),
                                      num(v),
                                      num(e, 4),
                                      paper_error(rep)};
      for (auto& c : cost_cells(rep))
        row.push_back(std::move(c));
      t.add(row);
      if (rep.contains("host"))
        host.add({r.name, r.algorithm, f, std::to_string(r.nodes),
                  num(rep["host"].value("wall_time_s", 0.0), 3),
                  num(rep["host"].value("peak_rss_bytes", 0.0))});
    }
  }
  t.write_csv(dir + "/fidelity.csv");
  host.write_csv(dir + "/host_cost.csv");
  return t.markdown();
}

} // namespace

PaperPlan fidelity_plan(const ReproduceOptions& o) {
  PaperPlan p;
  p.name = "";
  for (const auto& r : kRuns)
    for (const char* f : kFidelities) {
      RunConfig c = repro_config(r.machine, r.nodes, r.algorithm, o.root + "/" + r.scene, r.size);
      c.topology = parse_topology(r.topology);
      c.fidelity = parse_fidelity(f);
      if (r.memory_mib > 0) c.what_ifs.set("memory", {r.memory_mib * 1048576});
      if (!r.option_key.empty()) c.options.values[r.option_key] = r.option_value;
      p.points.push_back({key(r, f), c});
    }
  p.write = write_fidelity;
  return p;
}

} // namespace zc
