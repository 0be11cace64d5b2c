#pragma once
// The runs zcube makes: a simulation's report with the seeds' figures it corresponds to attached
// (repro/paper_figures), so that the simulator below knows nothing of the papers.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run/batch.hpp"
#include "run/report.hpp"

namespace zc {

// Adds "paper" (the matching figures and the relative errors) when the report matches any.
void attach_paper_figures(nlohmann::json& report);
// The report as JSON (the edge: a file, or a forked child's answer) with those figures attached.
nlohmann::json report_with_paper_figures(const Report& report);

// SimGrid settings (--cfg=..., --log=...) every point of this process's batches gets after its
// own: the --cfg/--log of reproduce, regress, calibrate and sweep.
void set_batch_simgrid_args(std::vector<std::string> args);

// What a node program's calls depend on (run/call_trace.hpp), as JSON: the algorithm, its options
// and frames, the scene, the size, the node count, the topology and the image comparison; not the
// machine, its what-ifs or the fidelity. A point's whole key adds those (reproduce's config_key).
nlohmann::json program_inputs(const RunConfig& c);

// One simulation's report, paper figures attached: the point runner of zcube's batches.
nlohmann::json simulate_point(const RunConfig& cfg);

// run_batch with simulate_point, recording and replaying (docs/simulator.md, "Record and
// replay") the points that differ only in their machine. `keep_traces`: the recordings are kept
// for the process's later batches (the calibration's steps), and every point records; otherwise
// only the points another of the batch can replay record.
std::vector<nlohmann::json>
simulate_batch(const std::vector<RunConfig>& points, int jobs,
               const std::function<void(const BatchProgress&)>& progress = {},
               bool keep_traces = false);

} // namespace zc
