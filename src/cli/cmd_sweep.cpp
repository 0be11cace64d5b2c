// zcube sweep: a design (repro/sweep_design.hpp) over list-valued run flags, each point its own
// simulation process (repro/sweep.hpp), with a CSV, a JSON and a plot of the swept quantity.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/paths.hpp"
#include "cli/sim_options.hpp"
#include "machine/units.hpp"
#include "repro/plot_script.hpp"
#include "repro/progress.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"
#include "repro/sweep.hpp"
#include "repro/sweep_design.hpp"
#include "repro/table.hpp"
#include "run/batch.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"
#ifdef ZCUBE_HAVE_MPI
#include <optional>

#include "mpi/mpi_session.hpp"
#include "mpi/sharded_batch.hpp"
#endif

namespace zc::cli {

// Quantities are checked alone, before anything runs: `--latency 275,27` is a usage error, not
// two failed points.
static void check_quantities(const std::vector<SweepAxis>& axes) {
  for (const auto& ax : axes)
    if (const WhatIfSpec* w = find_what_if(ax.flag))
      for (const auto& v : ax.values)
        parse_what_if(*w, v);
}

// The phases the algorithms time (their ctx.phase names; tests/cli/hostile.sh checks that this
// list holds every one in src/algo), for --plot-y phase:<name> before anything runs.
static const std::vector<std::string> kPhases = {"broadcast",
                                                 "distribute",
                                                 "load_estimation",
                                                 "local_zbuffer",
                                                 "merge",
                                                 "multibroadcast_uvs",
                                                 "multibroadcast_vertices",
                                                 "multireduce_load",
                                                 "multiscatter_triangles",
                                                 "output",
                                                 "partition",
                                                 "paste",
                                                 "pixel_merging",
                                                 "project",
                                                 "render",
                                                 "request_vertices",
                                                 "scatter_triangles",
                                                 "scatter_vertices",
                                                 "share",
                                                 "span_list_creation",
                                                 "zbuffer"};

// --plot-x is a swept flag and --plot-y a column the sweep can have: checked before any point
// runs, not after all of them.
static void check_plot_axes(const std::vector<SweepAxis>& axes, const std::string& plot_x,
                            const std::string& plot_y, bool no_plot) {
  if (no_plot) return;
  std::string swept;
  bool found = plot_x.empty();
  for (const auto& ax : axes) {
    swept += (swept.empty() ? "" : ", ") + ax.flag;
    found = found || ax.flag == plot_x;
  }
  if (!found)
    throw UsageError("--plot-x " + plot_x + ": not a swept flag (this sweep gives " + swept + ")");
  if (plot_y.starts_with("phase:") &&
      std::find(kPhases.begin(), kPhases.end(), plot_y.substr(6)) == kPhases.end()) {
    std::string names;
    for (const auto& p : kPhases)
      names += (names.empty() ? "" : ", ") + p;
    throw UsageError("--plot-y " + plot_y + ": no algorithm has that phase (" + names + ")");
  }
}

// The flags of zcube sweep besides the swept run flags.
struct SweepOptions {
  std::string out = "sweep", plot_x, plot_y = "virtual_s", plot_format = "png", design = "grid";
  std::string table;              // columns of the Markdown table printed after the run
  std::vector<std::string> where; // column=value: the rows that table shows
  int jobs = default_jobs();
  bool no_plot = false, baseline = false, yes = false, fail_on_oom = false;
  CLI::Option* jobs_opt = nullptr;
};

static void add_sweep_options(CLI::App& app, SweepOptions& o) {
  app.add_option("--design", o.design,
                 "grid (every combination of the values), oat (one flag at a time around the "
                 "base point, every flag's first value) or a CSV file of points (a header of "
                 "flag names, a row a point)")
      ->capture_default_str();
  app.add_option("--out", o.out, "directory for sweep.csv, sweep.json, sweep.png")
      ->capture_default_str();
  o.jobs_opt = app.add_option("--jobs", o.jobs, "points at once (per rank under mpirun: 1)")
                   ->check(CLI::Range(1, 4096))
                   ->capture_default_str();
  app.add_option("--plot-x", o.plot_x,
                 "flag on the plot's x axis (default: the first with several values)");
  app.add_option(
         "--plot-y", o.plot_y,
         "column on the plot's y axis: virtual_s, timed_s, speedup, efficiency, wall_s, messages, "
         "bytes, concurrent_volume_bytes, load_imbalance or phase:<name>")
      ->capture_default_str();
  app.add_option("--plot-format", o.plot_format, "png, svg or pdf")
      ->check(CLI::IsMember({"png", "svg", "pdf"}))
      ->capture_default_str();
  app.add_flag("--no-plot", o.no_plot, "skip the plot");
  app.add_flag("--baseline", o.baseline,
               "also run each algorithm's one-node reference (sequential; scanline for Kurc et "
               "al.; node-initiated for Blazek) for every combination of the other flags, so "
               "every row gets speedup and efficiency");
  app.add_option("--table", o.table,
                 "print a Markdown table of these comma-separated columns after the run (e.g. "
                 "algorithm,latency,timed_s,speedup; numbers to 4 significant digits)");
  app.add_option("--where", o.where,
                 "column=value: only the rows whose column reads value go into --table; "
                 "repeatable");
  app.add_flag("--yes", o.yes,
               "run a sweep of more than " + std::to_string(kSweepPointsWithoutYes) + " points");
  app.add_flag("--fail-on-oom", o.fail_on_oom,
               "exit 1 when a point runs out of modelled node memory (by default such a point is "
               "a row with status out_of_memory: an outcome, as in the papers' tables)");
}

// The points of the design over the given flags; `axes` becomes the design's flags.
static std::vector<SweepPoint> design_points(const SweepOptions& o, std::vector<SweepAxis>& axes) {
  const std::string scene = default_scene_path();
  const Locate locate = [](const std::string& f) { return data_file(f); };
  if (o.design != "grid" && o.design != "oat") {
    if (!axes.empty())
      throw UsageError("--design " + o.design + ": a point file gives every flag; give the " +
                       "swept flags in its columns, not as --" + axes.front().flag);
    PointFile f = read_point_file(o.design, scene, locate);
    axes = f.axes;
    return f.points;
  }
  if (axes.empty())
    throw UsageError("sweep: give at least one flag, e.g. --nodes 1,2,4,8 (or --design FILE.csv)");
  return o.design == "oat" ? expand_one_at_a_time(axes, scene, locate)
                           : expand_sweep(axes, scene, locate);
}

// Before anything runs: the plot's axes, the size of the sweep, every point's input files.
static void check_sweep(SweepOptions& o, const std::vector<SweepAxis>& axes,
                        const std::vector<SweepPoint>& points) {
  check_quantities(axes);
  for (const auto& w : o.where)
    if (w.find('=') == std::string::npos || w.front() == '=')
      throw UsageError("--where '" + w + "': expected column=value (e.g. nodes=16)");
  if (!o.where.empty() && o.table.empty()) throw UsageError("--where: chooses the rows of --table");
  if (o.plot_x.empty())
    for (const auto& ax : axes)
      if (ax.values.size() > 1) {
        o.plot_x = ax.flag;
        break;
      }
  check_plot_axes(axes, o.plot_x, o.plot_y, o.no_plot);
  const auto& known = sweep_value_columns();
  if (!o.plot_y.starts_with("phase:") &&
      std::find(known.begin(), known.end(), o.plot_y) == known.end())
    throw UsageError(
        "--plot-y " + o.plot_y +
        ": not a sweep column (virtual_s, timed_s, speedup, efficiency, wall_s, messages, "
        "bytes, concurrent_volume_bytes, load_imbalance or phase:<name>)");
  const bool has_baseline = std::any_of(points.begin(), points.end(), is_baseline);
  if ((o.plot_y == "speedup" || o.plot_y == "efficiency") && !has_baseline)
    throw UsageError("--plot-y " + o.plot_y +
                     ": the sweep has no reference run on one node to compare with (add "
                     "--baseline, or the reference (sequential, scanline, node-initiated) to "
                     "--algorithm and 1 to --nodes)");
  const double minutes = double(points.size()) * kHostSecondsPerPoint / o.jobs / 60;
  if (points.size() > kSweepPointsWithoutYes) {
    std::cerr << "sweep: " << points.size() << " points, at least " << std::ceil(minutes)
              << " min of host time with " << o.jobs << " at a time (about " << kHostSecondsPerPoint
              << " s a small point; more for large scenes and nodes)\n";
    if (!o.yes)
      throw UsageError("sweep: " + std::to_string(points.size()) + " points, more than " +
                       std::to_string(kSweepPointsWithoutYes) + ": add --yes to run them");
  }
  if (std::none_of(points.begin(), points.end(), [](const auto& p) { return bool(p.config); }))
    throw UsageError("sweep: no point can run: " + points.front().error);
  check_point_inputs(points); // a missing scene is one usage error, not a failed row per point
}

// Runs the points (shared among MPI ranks under mpirun); empty on the ranks other than 0.
static std::vector<nlohmann::json> run_sweep_points(const std::vector<SweepPoint>& points,
                                                    SweepOptions& o, bool& root) {
  std::size_t invalid = 0;
  for (const auto& p : points)
    invalid += !p.config;
#ifdef ZCUBE_HAVE_MPI
  std::optional<MpiSession> mpi;
  if (launched_by_mpirun()) {
    mpi.emplace();
    if (!o.jobs_opt->count()) o.jobs = 1; // the ranks already fill the cores
  }
  root = !mpi || mpi->rank() == 0;
  const int ranks = mpi ? mpi->size() : 1;
#else
  root = true;
  const int ranks = 1;
#endif
  if (root)
    std::cerr << "sweep: " << points.size() << " points (" << invalid << " invalid: not run), "
              << o.jobs << " at a time"
              << (ranks > 1 ? " on each of " + std::to_string(ranks) + " MPI ranks" : "") << "\n";
  return run_points(points, [&](const std::vector<RunConfig>& cfgs) {
#ifdef ZCUBE_HAVE_MPI
    if (mpi)
      return run_batch_sharded(cfgs, o.jobs, simulate_point,
                               root ? progress_printer("sweep (rank 0's share)")
                                    : std::function<void(const BatchProgress&)>{});
#endif
    return simulate_batch(cfgs, o.jobs, progress_printer("sweep", cfgs.size()));
  });
}

// A cell of --table: text as it is, numbers to 4 significant digits, nothing for null.
static std::string table_cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  if (!v.is_number_float()) return v.dump();
  std::ostringstream s;
  s << std::setprecision(4) << v.get<double>();
  return s.str();
}

// --table COLUMNS with --where column=value filters, as Markdown (UsageError for a column no row
// has, checked before anything is printed).
static std::string markdown_table(const nlohmann::json& rows, const SweepOptions& o) {
  const auto cols = split_list(o.table, "table");
  for (const auto& c : cols)
    if (std::none_of(rows.begin(), rows.end(), [&](const auto& r) { return r.contains(c); }))
      throw UsageError("--table " + c + ": no row has that column");
  Table t{cols, {}};
  for (const auto& r : rows) {
    bool keep = true;
    for (const auto& w : o.where) {
      const auto eq = w.find('=');
      keep =
          keep && r.contains(w.substr(0, eq)) && table_cell(r[w.substr(0, eq)]) == w.substr(eq + 1);
    }
    if (!keep) continue;
    std::vector<std::string> cells;
    for (const auto& c : cols)
      cells.push_back(table_cell(r.value(c, nlohmann::json(nullptr))));
    t.add(std::move(cells));
  }
  return t.markdown();
}

// The plot of the swept quantity; "" when drawn, else why not (a missing plotting library is an
// outcome, not a failure: the tables are written).
static std::string draw_sweep_plot(const SweepOptions& o, const nlohmann::json& rows,
                                   bool& failed) {
  const std::string plot = o.out + "/sweep." + o.plot_format;
  if (std::none_of(rows.begin(), rows.end(), [](const auto& r) { return r["status"] == "ok"; }))
    return "no point ran: nothing to plot";
  PlotOutcome outcome = PlotOutcome::failed;
  try { // to a temporary file renamed into place (util/output_file.hpp)
    write_file_atomically(plot, [&](const std::string& tmp) {
      outcome = plot_script_outcome(source_root(), {"--format", o.plot_format, "--sweep",
                                                    o.out + "/sweep.csv", o.plot_x, o.plot_y, tmp});
      return outcome == PlotOutcome::drawn;
    });
    return "";
  } catch (const std::runtime_error&) { // the script said why on stderr
  }
  // The script said so in one line ("matplotlib not found"): not said again.
  if (outcome == PlotOutcome::library_missing) return "skipped";
  failed = true;
  return "plot not drawn";
}

// The outcome of every point: out of memory is a result (a row), unless --fail-on-oom; an error
// or a deadlock is a failure.
static int count_failures(const nlohmann::json& rows, const SweepOptions& o, int& oom) {
  int failed = 0;
  for (const auto& r : rows) {
    const std::string st = r["status"];
    if (st == "ok" || st == "invalid") continue;
    if (st == "out_of_memory") {
      ++oom;
      if (!o.fail_on_oom) continue;
    }
    ++failed;
    std::cerr << "sweep: point " << r["index"] << " failed: " << r["error"].get<std::string>()
              << "\n";
  }
  return failed;
}

static int cmd_sweep(std::vector<std::string> args) {
  CLI::App app{"Run a design of points over comma-separated flag values, one process a point "
               "(e.g. --nodes 1,2,4,8 --latency x0.1,x1 --algorithm pair-rs,aapc-hbp)",
               "zcube sweep"};
  std::map<std::string, std::string> given;
  add_run_flag_options(
      app, given, [](const RunFlag&) { return true; }, true);
  SweepOptions o;
  add_sweep_options(app, o);
  app.footer(whatif_help()); // units, ranges and each machine's figures
  BatchSimGridFlags simgrid;
  simgrid.add_to(app);
  if (int rc = parse(app, args); rc >= 0) return rc;
  simgrid.apply();

  std::vector<SweepAxis> axes;
  for (const auto& f : run_flag_names())
    if (!given[f].empty()) axes.push_back({f, split_list(given[f], f)});
  auto points = design_points(o, axes);
  if (o.baseline)
    add_baselines(axes, points, default_scene_path(),
                  [](const std::string& f) { return data_file(f); });
  check_sweep(o, axes, points);
  prepare_sweep_dir(o.out); // before anything runs: no stale sweep.csv survives an interruption
  bool root = true;
  const auto reports = run_sweep_points(points, o, root);
  if (!root) return 0;
  nlohmann::json rows = sweep_rows(axes, points, reports);
  add_speedups(points, reports, rows);
  write_sweep(axes, rows, reports, o.out);
  int oom = 0;
  const int failed = count_failures(rows, o, oom);
  bool plot_failed = false;
  const std::string not_drawn =
      o.no_plot || o.plot_x.empty() ? "skipped" : draw_sweep_plot(o, rows, plot_failed);
  if (!not_drawn.empty() && not_drawn != "skipped") std::cerr << "sweep: " << not_drawn << "\n";
  std::cout << "sweep: " << rows.size() << " points, " << failed << " failed"
            << (oom ? ", " + std::to_string(oom) + " out of memory" : "") << "; wrote " << o.out
            << "/sweep.csv, sweep.json" << (not_drawn.empty() ? ", sweep." + o.plot_format : "")
            << "\n";
  if (!o.table.empty()) std::cout << markdown_table(rows, o);
  return failed || plot_failed ? 1 : 0;
}

ZC_COMMAND("sweep", "run the Cartesian product of flag values (what-if studies)", cmd_sweep);

} // namespace zc::cli
