#pragma once
// `zcube reproduce`: the papers' tables and speed-up curves on the calibrated machine models. Each
// paper is a plan: the simulation points it needs (run together, each in its own process) and a
// writer that turns their reports into fixed-name CSV files and a README.md side by side with the
// paper's figures. Plots are drawn afterwards by scripts/plot_results.py from the CSV files.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run/batch.hpp"
#include "sim/simulation.hpp"

namespace zc {

struct ReproduceOptions {
  std::string root = "."; // source tree: scenes/
  std::string out = "results";
  std::vector<std::string> papers; // names in papers(); empty: all, with the fidelity and claims
  bool full = false; // Blazek's whole grid (1..2048 spheres), compositing's to 1024 nodes; slow
  int jobs = 2;
  bool plots = true;
  std::string plot_format = "png"; // png, svg or pdf
  bool verbose = true;
  // How the points run: a local batch by default; `mpirun zcube reproduce` passes a batch sharded
  // over the ranks, and only the rank that gets the reports (write = true) writes files.
  std::function<std::vector<nlohmann::json>(const std::vector<RunConfig>&, int,
                                            const std::function<void(const BatchProgress&)>&)>
      runner;
  bool write = true;
  // With every paper: also the calibration's fit and its validation (results/calibration/:
  // leave-one-scene-out folds, Charles et al.'s speed-ups predicted, plausibility of every cost).
  bool calibration = true;
  // Write into a paper's directory even when that loses rows it holds (the --full tables).
  bool overwrite = false;
};

struct ReproPoint {
  std::string key; // unique within a plan
  RunConfig cfg;
};
using Reports = std::map<std::string, nlohmann::json>; // by point key

// A space-time diagram of one point: the point runs with a timeline, and reproduce
// draws it into the plan's directory with scripts/plot_gantt.py.
struct GanttChart {
  std::string key, file, caption;
};

struct PaperPlan {
  std::string name; // the output subdirectory (empty: files at the top of `out`)
  std::vector<ReproPoint> points;
  std::vector<GanttChart> gantt;
  // Writes the plan's files under dir from the reports of its points; returns what it has to say
  // in results/README.md (Markdown; empty for nothing).
  std::function<std::string(const Reports&, const std::string& dir)> write;
  // Why writing into dir would lose results it holds (e.g. the --full tables), or empty. Such a
  // plan writes beside it, into dir + "-quick", unless overwrite is set.
  std::function<std::string(const std::string& dir)> would_degrade;
  bool plotted = true; // scripts/plot_results.py draws its files (a part named after the plan)
};

PaperPlan kurc_plan(const ReproduceOptions& o);
PaperPlan charles_plan(const ReproduceOptions& o);
PaperPlan blazek_plan(const ReproduceOptions& o);
PaperPlan fidelity_plan(const ReproduceOptions& o); // fidelity.csv: error against cost
// results/compositing/: every compositing strategy on the three machines
// (reproduce_compositing.cpp)
PaperPlan compositing_plan(const ReproduceOptions& o);

// Where a plan's files go: out/name, or out/name-quick when that would lose rows out/name holds
// (and overwrite is not set); the note says why (empty when nothing moved).
std::string plan_directory(const ReproduceOptions& o, const PaperPlan& p, std::string* note);

// Runs the selected plans (and the fidelity table when all papers are selected), writes
// everything, draws the plots; returns the process exit status (non-zero when a point failed in a
// way that is not a modelled out-of-memory). Never degrades what `out` holds: a plan whose
// directory has more than this run would write goes beside it (see PaperPlan::would_degrade).
// UsageError before any simulation when `out` cannot be a directory.
int reproduce(const ReproduceOptions& o);

// Helpers shared by the plans.
RunConfig repro_config(const std::string& machine, int nodes, const std::string& algorithm,
                       const std::string& scene, int size);
// The one time every paper's speed-up divides, on both sides (docs/papers.md), in `zcube
// reproduce` and in `zcube sweep` alike: the report's timed_s, the paper's timed region when the
// algorithm marks one (elastic's per-picture loop; Kurc et al.'s three Table 2 columns, the
// longest time one node spent in them), else the whole run (Blazek's methods).
double timed_s(const nlohmann::json& report);
// The whole run (the report's virtual_time_s): the `virtual_s` column of every CSV.
double whole_run_s(const nlohmann::json& report);
// A failed point's status as the tables' `status` column states it ("out_of_memory", "error").
std::string status_of(const nlohmann::json& report);
// The draws of the uncertainty model every point of the papers' tables is priced under
// (docs/uncertainty.md): the same draws for every point, so that a speed-up's band pairs them.
inline constexpr int kReproduceDraws = 100;
void with_bands(PaperPlan& plan);
// The draws' values of timed_s (the timed region, else the whole run), of a phase's critical
// node, or of the sum of some phases, one a draw, NaN where a draw failed; empty without bands.
std::vector<double> band_timed_s(const nlohmann::json& report);
std::vector<double> band_phases_s(const nlohmann::json& report,
                                  const std::vector<std::string>& phases);
// The 5th and 95th percentiles of num[d] / den[d] over the draws both have (NaN, NaN if none).
std::pair<double, double> ratio_band(const std::vector<double>& num,
                                     const std::vector<double>& den);
bool ok(const nlohmann::json& report);
bool out_of_memory(const nlohmann::json& report);
// The README section that shows a plan's Gantt charts.
std::string gantt_markdown(const std::vector<GanttChart>& charts);

} // namespace zc
