#pragma once
// The report of one run (docs/user-guide.md, "One run"), typed: built by the run's last step
// (run/run_steps.hpp) from what each node recorded, the same for the SimGrid backend (virtual
// times) and the MPI backend (measured times), and written to JSON only at the edge
// (report_json), where a file is written or a forked child hands it back.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "machine/machine.hpp"
#include "run/image_check.hpp"
#include "run/node_record.hpp"
#include "run/sim_cost.hpp"
#include "run/what_if.hpp"

namespace zc {

// What ran where: "machine", "platform", "nodes", "topology", "fidelity", "algorithm", "options"
// (every option, the defaults included: a report says which variant ran), "frames", "scene".
struct RunHeader {
  std::string machine, platform, topology, fidelity, algorithm;
  int nodes = 0;
  nlohmann::json options = nlohmann::json::object();
  int frames = 1;
  struct SceneSummary {
    std::string path;
    std::size_t triangles = 0, vertices = 0;
    int width = 0, height = 0;
  } scene;
};

// The machine a simulated run was priced on (what-ifs and draw applied): the report's "model"
// and "what_if".
struct ModelSection {
  NetworkParams net;
  double node_memory_bytes = 0, os_resident_bytes = 0;
  CostTable node0_cpu; // every counted operation's cost on node 0 (docs/machines.md)
  WhatIfs what_ifs;    // the what-ifs in force (none: empty)
};

// What the run cost the host computer zcube ran on (the report's "host").
struct HostUse {
  double wall_time_s = 0;
  std::size_t peak_rss_bytes = 0;
  std::optional<long> page_faults_timed; // measured runs: node 0's, in the timed part
  std::optional<double> core_share;      // measured runs: the lowest rank's CPU/wall share
};

// A run on real processors: its clock and the processors each rank ran on.
struct Measurement {
  std::string clock;
  nlohmann::json processors = nlohmann::json::array();
};

struct Report {
  RunHeader header;
  std::string status = "ok"; // "ok", "out_of_memory" or "error"
  std::string error;
  double virtual_time_s = 0; // measured runs: the slowest rank's wall-clock time
  // The P nodes in rank order, then the host computer when it ran.
  std::vector<NodeRecord> records;
  // The node whose algorithm metrics are the run's (Algorithm::metrics_node; node 0 by default):
  // they are written at the report's top level.
  int metrics_rank = 0;
  std::optional<ModelSection> model;      // simulated runs
  std::optional<SimCost> simulation_cost; // simulated runs
  std::optional<Measurement> measured;    // measured runs
  ImageVerdict image;
  HostUse host;
  // Priced after the run from draws of the uncertainty model (sim/bands.hpp): "bands",
  // "sensitivity" and each phase's band, by phase name. Null or empty: none.
  nlohmann::json bands, sensitivity;
  std::map<std::string, nlohmann::json> phase_bands;

  bool ok() const { return status == "ok"; }
  int nodes() const { return header.nodes; }
};

// The phases in the order the nodes first entered them.
std::vector<std::string> phase_names(const std::vector<NodeRecord>& records);
// The paper's timed region (docs/papers.md): the longest (end - start) over the nodes that
// started one; none when no node did (the whole run is timed).
std::optional<double> timed_region_s(const Report& r);

// The report as JSON: the one place its keys are spelt.
nlohmann::json report_json(const Report& r);

// The host process's peak resident set (the report's host.peak_rss_bytes).
std::size_t peak_rss_bytes();

} // namespace zc
