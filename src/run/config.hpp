#pragma once
// What to run, whatever the backend (SimGrid simulation or MPI processes): the machine with its
// what-ifs, the algorithm with its options, the scene; and what a run returns, its report and the
// delivered pictures.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "algo/algorithm.hpp"
#include "machine/topology.hpp"
#include "machine/uncertainty.hpp"
#include "raster/framebuffer.hpp"
#include "run/fidelity.hpp"
#include "run/image_check.hpp"
#include "run/report.hpp"
#include "run/what_if.hpp"

namespace zc {

struct RunConfig {
  std::string machine = "ipsc2"; // built-in name or path to a platform XML
  int nodes = 1;
  Topology topology = Topology::Cube;
  Fidelity fidelity = Fidelity::Circuit;
  WhatIfs what_ifs; // machine figures changed for this run (run/what_if.hpp)
  std::string algorithm = "sequential";
  std::shared_ptr<const Algorithm> custom; // runs instead of `algorithm` (tests, benchmarks)
  AlgorithmOptions options;
  std::string scene_path;
  int width = 0, height = 0;           // > 0 overrides the scene's size
  bool compare_with_sequential = true; // render on the host and compare images
  // Where the references already drawn are (a batch draws each once before it forks); empty:
  // the run draws its own.
  ReferenceLookup reference_lookup;
  // Passed to SimGrid after zcube's own settings, so they win: "--cfg=name:value", "--log=...".
  std::vector<std::string> simgrid_args;
  bool timeline = false; // record every node's events (the report's "timeline"; --trace, --gantt)
  // One draw of the uncertainty model (machine/uncertainty.hpp) priced on top of the machine and
  // its what-ifs; null: the nominal machine.
  std::shared_ptr<const ModelDraw> draw;
  // Draws of the uncertainty model priced after the run, in its process (sim/bands.hpp: the
  // report's "bands"); 0: none. The same seed gives every point of a study the same draws.
  int band_draws = 0;
  std::uint64_t band_seed = 1;
  // The uncertainty model the draws come from; null: the machine's (uncertainty_spec).
  std::shared_ptr<const UncertaintySpec> band_spec;
};

struct RunResult {
  Report report;                   // report_json(report) at the edge
  std::vector<Framebuffer> images; // one per frame (node-delivered)
  // Whether the run ended well, and why not (e.g. out of node memory): the report's own.
  bool ok() const { return report.ok(); }
  const std::string& error() const { return report.error; }
};

} // namespace zc
