#pragma once
// `zcube sweep`: the Cartesian product of list-valued run flags (--nodes 1,2,4 --latency
// 10us,1ms ...), each point one simulation in its own process. A point whose flags are invalid or
// whose run fails keeps its row with the reason; the others are not affected.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run/run_flags.hpp"
#include "sim/simulation.hpp"

namespace zc {

struct SweepAxis {
  std::string flag;                // without dashes: "nodes", "latency", ...
  std::vector<std::string> values; // one or more
};

// Splits "1,2,4" (empty items are an error naming the flag).
std::vector<std::string> split_list(const std::string& text, const std::string& flag);

// Where a --scene or --machine value is found (cli/paths.hpp: the bundled scenes and platforms
// when the value is not a file from the working directory); empty: as given.
using Locate = std::function<std::string(const std::string&)>;

struct SweepPoint {
  std::map<std::string, std::string> values; // flag -> value, for every axis
  std::optional<RunConfig> config;           // empty when the flags are invalid
  std::string error;                         // why not
};

// The point the flags describe: its configuration, or the reason it has none.
SweepPoint make_point(std::map<std::string, std::string> values, const std::string& scene,
                      const Locate& locate = {});

// Every combination, the first axis varying slowest. `scene` is the default scene path.
std::vector<SweepPoint> expand_sweep(const std::vector<SweepAxis>& axes, const std::string& scene,
                                     const Locate& locate = {});

// Runs the points that have a configuration through `runner` (a local or a sharded batch) and
// returns one report per point, an invalid point's being {"status": "error", "error": reason}.
// Empty when the runner returns nothing (the other ranks of a sharded batch).
using BatchRunner = std::function<std::vector<nlohmann::json>(const std::vector<RunConfig>&)>;
std::vector<nlohmann::json> run_points(const std::vector<SweepPoint>& points,
                                       const BatchRunner& runner);

// A swept flag's columns in a row: its value (a number for integer flags such as nodes), and for a
// what-if its numeric twins: the SI value when absolute ("latency_s"), the factor when relative
// ("latency_factor"); the other is empty.
void add_axis_columns(nlohmann::json& row, const std::string& flag, const std::string& text);

// One row per point: the axis values, then status, error, virtual_s, timed_s (the paper's timed
// region when the algorithm marks one, else virtual_s), wall_s, messages, bytes,
// concurrent_volume_bytes, load_imbalance, image_sha256, identical, and one "phase:<name>" column
// (max over nodes, s) per phase any point has.
nlohmann::json sweep_rows(const std::vector<SweepAxis>& axes, const std::vector<SweepPoint>& points,
                          const std::vector<nlohmann::json>& reports);

// The run of the point's reference (Algorithm::reference: sequential, scanline for Kurc et al.,
// node-initiated for Blazek; docs/papers.md) on one node with the same values as the point on
// every axis but the algorithm, its options and the node count: the baseline of its speed-up.
// A baseline is a reference's own point on one node without algorithm options.
bool is_baseline(const SweepPoint& p);
// Appends, for every combination of the non-algorithm axes and reference that has none, that
// baseline point (zcube sweep --baseline). Its values on the algorithm option axes are "".
void add_baselines(const std::vector<SweepAxis>& axes, std::vector<SweepPoint>& points,
                   const std::string& scene, const Locate& locate = {});
// Adds speedup = T(baseline) / T(point), T the timed region (timed_s), and efficiency = speedup /
// nodes to every row (null where there is no baseline or a run failed), when any point is a
// baseline; returns whether it did.
bool add_speedups(const std::vector<SweepPoint>& points, const std::vector<nlohmann::json>& reports,
                  nlohmann::json& rows);

// The columns `--plot-y` may name before the sweep runs ("phase:<name>" is checked after).
const std::vector<std::string>& sweep_value_columns();

// Removes the sweep.* files an earlier sweep left in dir (so an interrupted sweep leaves none
// that looks current); UsageError when dir cannot be a directory.
void prepare_sweep_dir(const std::string& dir);

// sweep.csv and sweep.json under dir (the JSON has the rows and the full reports).
void write_sweep(const std::vector<SweepAxis>& axes, const nlohmann::json& rows,
                 const std::vector<nlohmann::json>& reports, const std::string& dir);

} // namespace zc
