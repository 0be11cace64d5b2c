// zcube sweep: the Cartesian product of list-valued run flags, each point its own simulation
// process (repro/sweep.hpp), with a CSV, a JSON and a plot of the swept quantity.
#include <algorithm>
#include <iostream>

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
    for (const auto& v : ax.values) {
      if (ax.flag == "latency" || ax.flag == "per-hop" || ax.flag == "host-latency")
        parse_time(v, "--" + ax.flag, Unit::Required);
      if (ax.flag == "bandwidth" || ax.flag == "host-bandwidth")
        parse_bandwidth(v, "--" + ax.flag, Unit::Required);
      if (ax.flag == "memory") parse_bytes(v, "--memory", Unit::Required);
    }
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

static int cmd_sweep(std::vector<std::string> args) {
  CLI::App app{"Run the Cartesian product of comma-separated flag values, one process a point "
               "(e.g. --nodes 1,2,4,8 --latency 10us,275us --algorithm pair-rs,aapc-hbp)",
               "zcube sweep"};
  std::map<std::string, std::string> given;
  for (const auto& f : run_flag_names())
    app.add_option("--" + f, given[f], "comma-separated values of zcube run --" + f);
  std::string out = "sweep", plot_x, plot_y = "virtual_s", plot_format = "png";
  int jobs = default_jobs();
  bool no_plot = false, baseline = false;
  app.add_option("--out", out, "directory for sweep.csv, sweep.json, sweep.png")
      ->capture_default_str();
  [[maybe_unused]] auto* jobs_opt =
      app.add_option("--jobs", jobs, "points at once (per rank under mpirun: 1)")
          ->check(CLI::Range(1, 4096))
          ->capture_default_str();
  app.add_option("--plot-x", plot_x,
                 "flag on the plot's x axis (default: the first with several values)");
  app.add_option(
         "--plot-y", plot_y,
         "column on the plot's y axis: virtual_s, timed_s, speedup, efficiency, wall_s, messages, "
         "bytes, concurrent_volume_bytes, load_imbalance or phase:<name>")
      ->capture_default_str();
  app.add_option("--plot-format", plot_format, "png, svg or pdf")
      ->check(CLI::IsMember({"png", "svg", "pdf"}))
      ->capture_default_str();
  app.add_flag("--no-plot", no_plot, "skip the plot");
  app.add_flag("--baseline", baseline,
               "also run each algorithm's one-node reference (sequential; scanline for Kurc et "
               "al.; node-initiated for Blazek) for every combination of the other flags, so "
               "every row gets speedup and efficiency");
  app.footer(whatif_help()); // units, ranges and each machine's figures
  BatchSimGridFlags simgrid;
  simgrid.add_to(app);
  if (int rc = parse(app, args); rc >= 0) return rc;
  simgrid.apply();

  std::vector<SweepAxis> axes;
  for (const auto& f : run_flag_names())
    if (!given[f].empty()) axes.push_back({f, split_list(given[f], f)});
  if (axes.empty()) throw UsageError("sweep: give at least one flag, e.g. --nodes 1,2,4,8");
  check_quantities(axes);
  if (plot_x.empty())
    for (const auto& ax : axes)
      if (ax.values.size() > 1) {
        plot_x = ax.flag;
        break;
      }
  check_plot_axes(axes, plot_x, plot_y, no_plot);
  auto points = expand_sweep(axes, default_scene_path());
  if (baseline) add_baselines(axes, points, default_scene_path());
  const auto& known = sweep_value_columns();
  bool has_baseline = false;
  for (const auto& p : points)
    has_baseline = has_baseline || is_baseline(p);
  if (!plot_y.starts_with("phase:") && std::find(known.begin(), known.end(), plot_y) == known.end())
    throw UsageError(
        "--plot-y " + plot_y +
        ": not a sweep column (virtual_s, timed_s, speedup, efficiency, wall_s, messages, "
        "bytes, concurrent_volume_bytes, load_imbalance or phase:<name>)");
  if ((plot_y == "speedup" || plot_y == "efficiency") && !has_baseline)
    throw UsageError("--plot-y " + plot_y +
                     ": the sweep has no reference run on one node to compare with (add "
                     "--baseline, or the reference (sequential, scanline, node-initiated) to "
                     "--algorithm and 1 to --nodes)");
  prepare_sweep_dir(out); // before anything runs: no stale sweep.csv survives an interruption
  std::size_t invalid = 0;
  for (const auto& p : points)
    invalid += !p.config;
#ifdef ZCUBE_HAVE_MPI
  // Under mpirun: the points are shared among the ranks; rank 0 writes the files.
  std::optional<MpiSession> mpi;
  if (launched_by_mpirun()) {
    mpi.emplace();
    if (!jobs_opt->count()) jobs = 1; // the ranks already fill the cores
  }
  const bool root = !mpi || mpi->rank() == 0;
  const int ranks = mpi ? mpi->size() : 1;
#else
  const bool root = true;
  const int ranks = 1;
#endif
  if (root)
    std::cerr << "sweep: " << points.size() << " points (" << invalid << " invalid), " << jobs
              << " at a time"
              << (ranks > 1 ? " on each of " + std::to_string(ranks) + " MPI ranks" : "") << "\n";
  const auto reports = run_points(points, [&](const std::vector<SimConfig>& cfgs) {
#ifdef ZCUBE_HAVE_MPI
    if (mpi)
      return run_batch_sharded(cfgs, jobs, simulate_point,
                               root ? progress_printer("sweep (rank 0's share)")
                                    : std::function<void(const BatchProgress&)>{});
#endif
    return simulate_batch(cfgs, jobs, progress_printer("sweep", cfgs.size()));
  });
  if (!root) return 0;
  nlohmann::json rows = sweep_rows(axes, points, reports);
  add_speedups(points, reports, rows);
  write_sweep(axes, rows, reports, out);
  int failed = 0;
  for (const auto& r : rows)
    if (r["status"] != "ok") { // an error, out of memory, a deadlock
      ++failed;
      std::cerr << "sweep: point " << r["index"] << " failed: " << r["error"].get<std::string>()
                << "\n";
    }
  const std::string plot = "sweep." + plot_format;
  bool drawn = false;
  if (!no_plot && !plot_x.empty()) {
    bool column = false;
    for (const auto& r : rows)
      column = column || r.contains(plot_y);
    if (!column) {
      std::cerr << "zcube: error: --plot-y " << plot_y << ": no point has that column\n";
      return 2;
    }
    try { // to a temporary file renamed into place (util/output_file.hpp)
      write_file_atomically(out + "/" + plot, [&](const std::string& tmp) {
        return run_plot_script(source_root(), {"--format", plot_format, "--sweep",
                                               out + "/sweep.csv", plot_x, plot_y, tmp});
      });
      drawn = true;
    } catch (const std::runtime_error&) { // the script said why on stderr
    }
    if (!drawn) std::cerr << "sweep: plot not drawn\n";
  }
  std::cout << "sweep: " << rows.size() << " points, " << failed << " failed; wrote " << out
            << "/sweep.csv, sweep.json" << (drawn ? ", " + plot : "") << "\n";
  return failed || (!no_plot && !plot_x.empty() && !drawn) ? 1 : 0;
}

ZC_COMMAND("sweep", "run the Cartesian product of flag values (what-if studies)", cmd_sweep);

} // namespace zc::cli
