#pragma once
// Flags shared by every command that simulates: machine, nodes, topology, fidelity and the what-if
// overrides (SimGrid-style units: 275us, 2.8MBps, 16MiB).
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "sim/simulation.hpp"

namespace zc::cli {

struct SimFlags {
  std::string machine = "ipsc2", topology = "cube", fidelity = "circuit";
  int nodes = 1;
  std::string latency, bandwidth, per_hop, cpu_scale, memory, cost_scale;
  CLI::Option* nodes_option = nullptr; // a platform .xml gives the node count unless --nodes does

  void add_to(CLI::App& app);
  // The given flags as text (sim/run_flags.hpp), for config_from_flags.
  std::map<std::string, std::string> flags() const;
  // Fills cfg's machine, nodes, topology, fidelity and overrides (UsageError on bad values).
  void apply(SimConfig& cfg) const;
};

} // namespace zc::cli
