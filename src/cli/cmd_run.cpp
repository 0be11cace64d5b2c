// zcube run: one simulation of an algorithm on a machine model.
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/paths.hpp"
#include "cli/sim_options.hpp"
#include "raster/image_io.hpp"
#include "repro/band_text.hpp"
#include "repro/gantt_chart.hpp"
#include "repro/paper_figures.hpp"
#include "repro/provenance.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"
#include "run/run_flags.hpp"
#include "scene/load.hpp"
#include "sim/bands.hpp"
#include "sim/simgrid_args.hpp"
#include "trace/trace_file.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"
#include "util/stdout_result.hpp"
#ifdef ZCUBE_HAVE_MPI
#include "mpi/mpi_run.hpp"
#include "mpi/mpi_session.hpp"
#endif

namespace zc::cli {

// --trace FILE and --gantt FILE: where the run's timeline goes (none: not recorded).
struct TimelineOutputs {
  std::string trace, gantt;
  bool wanted() const { return !trace.empty() || !gantt.empty(); }
};

// Writes the report and pictures and prints the summary (rank 0 only under MPI).
static int finish(const RunResult& r, nlohmann::json j, const std::string& report,
                  const std::string& image, const std::string& depth, const TimelineOutputs& tl) {
  j["provenance"] = provenance();
  if (!report.empty()) write_result_file(report, j.dump(2) + "\n");
  if (!tl.trace.empty()) write_trace(j, tl.trace);
  if (!tl.gantt.empty() && !draw_gantt(j, tl.gantt, source_root())) {
    std::cerr << "zcube: error: --gantt " << tl.gantt << ": scripts/plot_gantt.py failed\n";
    return 1;
  }
  if (!r.ok()) {
    std::cerr << "zcube: error: " << r.error() << "\n";
    return 1;
  }
  if (!image.empty() && !r.images.empty()) write_png(r.images.back(), image);
  if (!depth.empty() && !r.images.empty()) write_depth_exr(r.images.back(), depth);
  std::cout << std::setprecision(6) << j["algorithm"].get<std::string>() << " on "
            << j["machine"].get<std::string>() << " (" << j["nodes"]
            << (j["nodes"] == 1 ? " node, " : " nodes, ") << j["topology"].get<std::string>()
            << ", " << j["fidelity"].get<std::string>()
            << "): " << (j.value("measured", false) ? "measured" : "virtual") << " time "
            << j["virtual_time_s"].get<double>() << " s\n";
  if (j.contains("timed_s")) // what the speed-ups divide (docs/papers.md)
    std::cout << "  timed region (the paper's)   " << j["timed_s"].get<double>() << " s\n";
  for (const auto& p : j["phases"]) {
    std::cout << "  " << std::left << std::setw(28) << p["name"].get<std::string>() << " max "
              << p["max_s"].get<double>() << " s";
    if (p.contains("bands")) std::cout << "  " << band_text(p["bands"]);
    std::cout << "\n";
  }
  std::cout << bands_and_sensitivity_text(j);
  if (j.contains("paper"))
    for (const auto& f : j["paper"]) {
      std::cout << (f.value("what_if", false) ? "paper (what-ifs in force, not its machine): "
                                              : "paper: ")
                << f["source"].get<std::string>() << ": "
                << (f.contains("phase") ? f["phase"].get<std::string>() + " " : "")
                << f["quantity"].get<std::string>() << " " << f["paper"].get<double>();
      if (f.contains("predicted"))
        std::cout << ", predicted " << f["predicted"].get<double>() << " (error " << std::showpos
                  << 100 * f["rel_error"].get<double>() << std::noshowpos << " %)";
      std::cout << "\n";
    }
  if (j["image"].contains("sha256") && j["image"]["sha256"].is_null())
    std::cout << "image: none (" << j["algorithm"].get<std::string>() << " draws no picture)\n";
  else if (j["image"].contains("identical_to_sequential")) {
    std::cout << "image identical to the sequential renderer's: "
              << j["image"]["identical_to_sequential"];
    if (j["image"].contains("compared_with_sequential"))
      std::cout << " (" << j["image"]["compared_with_sequential"].get<std::string>() << " compared"
                << (j["image"].contains("differs_from_sequential")
                        ? "; " + j["image"]["differs_from_sequential"].get<std::string>() +
                              " differs"
                        : std::string())
                << ")";
    std::cout << "\n";
  }
  std::cout << "host wall time " << j["host"]["wall_time_s"].get<double>() << " s\n";
  return 0;
}

// What a run writes besides its summary, and how it is run.
struct RunOutputs {
  std::string image, depth, report, backend = "sim", sensitivity_plot;
  TimelineOutputs tl;
  BandsRequest bands;
  bool list = false;
};

static void add_output_options(CLI::App& app, RunOutputs& o) {
  app.add_option("--image", o.image, "write the (last) picture as PNG");
  app.add_option("--depth", o.depth, "write its depth as EXR");
  app.add_option("--report", o.report,
                 "write the report JSON (- or /dev/stdout: to standard output, the summary to "
                 "standard error)");
  app.add_option("--backend", o.backend,
                 "sim (SimGrid, virtual time) or mpi (real processes under mpirun, measured time)")
      ->check(CLI::IsMember({"sim", "mpi"}))
      ->capture_default_str();
  app.add_option("--trace", o.tl.trace,
                 "write the run's timeline: FILE.json (Chrome/Perfetto) or FILE.trace (Paje)");
  app.add_option("--gantt", o.tl.gantt, "draw a space-time diagram of the run: FILE.png|.svg|.pdf");
  app.add_option("--bands", o.bands.draws,
                 "N draws of the uncertainty model (docs/uncertainty.md): p05, p50 and p95 of "
                 "every time in the report")
      ->check(CLI::Range(0, 100000));
  app.add_option("--bands-seed", o.bands.seed, "the draws' seed (the same draws for every run)")
      ->capture_default_str();
  app.add_flag("--sensitivity", o.bands.sensitivity,
               "elasticity d ln T / d ln theta of every model parameter; prints the five largest");
  app.add_option("--sensitivity-plot", o.sensitivity_plot,
                 "draw the elasticities of the timed region as a tornado plot: FILE.png|.svg|.pdf");
  app.add_flag("--list", o.list, "list the algorithms and exit");
}

// Every output before the simulation, not after it: writable, not a directory, each its own file.
static void check_outputs(RunOutputs& o) {
  // The report on standard output: nothing else may go there from now on.
  if (names_stdout(o.report)) reserve_stdout_for_result();
  if (!o.sensitivity_plot.empty()) {
    check_tornado_path(o.sensitivity_plot);
    o.bands.sensitivity = true;
  }
  check_output_paths({{"--sensitivity-plot", o.sensitivity_plot},
                      {"--report", names_stdout(o.report) ? std::string() : o.report},
                      {"--image", o.image},
                      {"--depth", o.depth},
                      {"--trace", o.tl.trace},
                      {"--gantt", o.tl.gantt}});
  check_image_path(o.image, "--image");
  check_image_path(o.depth, "--depth");
  if (!o.tl.trace.empty()) check_trace_path(o.tl.trace);
  if (!o.tl.gantt.empty()) check_gantt_path(o.tl.gantt);
  if (o.backend == "mpi" && (o.bands.draws > 0 || o.bands.sensitivity))
    throw UsageError("--bands, --sensitivity: the MPI backend measures; it has no model to draw");
}

// A speed-up figure of a paper needs the sequential time on the same machine: one more
// simulation, in its own process and before this one (a forked child must not inherit a SimGrid
// engine). None when the run matches no such figure.
static std::optional<double> sequential_time_for_paper(const RunConfig& cfg) {
  const PaperRun run{cfg.algorithm, cfg.machine, topology_name(cfg.topology), cfg.scene_path,
                     cfg.nodes};
  const auto picture_size = [&cfg] {
    if (cfg.width > 0 && cfg.height > 0) return std::pair{cfg.width, cfg.height};
    const Scene s = load_scene(cfg.scene_path, LoadOptions{});
    return std::pair{s.width, s.height};
  };
  if (!needs_sequential_time(run, picture_size)) return std::nullopt;
  RunConfig seq = cfg;
  seq.algorithm = "sequential";
  seq.nodes = 1;
  seq.options = AlgorithmOptions{};
  seq.compare_with_sequential = false;
  const auto sr = run_simulation_isolated(seq);
  if (sr.value("status", "") != "ok") return std::nullopt;
  return timed_s(sr);
}

static int run_on_mpi([[maybe_unused]] const RunConfig& cfg, [[maybe_unused]] const RunOutputs& o) {
#ifdef ZCUBE_HAVE_MPI
  MpiSession mpi;
  RunResult r = run_mpi(cfg);
  return mpi.rank() == 0 ? finish(r, report_json(r.report), o.report, o.image, o.depth, o.tl) : 0;
#else
  throw UsageError("--backend mpi: this zcube was built without MPI (scripts/setup.sh installs "
                   "libopenmpi-dev; then rebuild)");
#endif
}

static int cmd_run(std::vector<std::string> args) {
  CLI::App app{"Simulate a parallel z-buffer algorithm on a 1990s machine model", "zcube run"};
  SimFlags sf;
  sf.add_to(app);
  // The rest of the run's description (algorithm, scene, size, frames, the algorithms' options),
  // from the one flag table (run/run_flags.hpp).
  std::map<std::string, std::string> more;
  add_run_flag_options(app, more, [](const RunFlag& f) {
    return f.group == RunFlag::Group::Option || f.name == "algorithm" || f.name == "scene" ||
           f.name == "size" || f.name == "frames";
  });
  RunOutputs o;
  add_output_options(app, o);
  if (int rc = parse(app, args); rc >= 0) return rc;
  if (o.list) {
    for (const auto& a : algorithms())
      std::cout << a.name << "  " << a.summary << "\n";
    return 0;
  }
  check_outputs(o);
  auto flags = sf.flags();
  flags.merge(given_flags(more));
  RunConfig cfg = config_from_flags(flags, default_scene_path());
  if ((!o.image.empty() || !o.depth.empty()) && !find_algorithm(cfg.algorithm).draws_picture)
    throw UsageError(std::string(o.image.empty() ? "--depth" : "--image") + ": " + cfg.algorithm +
                     " draws no picture");
  cfg.simgrid_args = sf.simgrid_args();
  check_simgrid_args(cfg.simgrid_args);
  std::cout << describe_overrides(cfg);
  cfg.timeline = o.tl.wanted();
  if (o.backend == "mpi") return run_on_mpi(cfg, o);
  const std::optional<double> seq_s = sequential_time_for_paper(cfg);
  RunResult r =
      o.bands.draws > 0 || o.bands.sensitivity ? run_with_bands(cfg, o.bands) : run_simulation(cfg);
  nlohmann::json j = report_with_paper_figures(r.report);
  if (r.ok() && !o.sensitivity_plot.empty() &&
      !draw_tornado(j, o.sensitivity_plot, source_root())) {
    std::cerr << "zcube: error: --sensitivity-plot " << o.sensitivity_plot
              << ": scripts/plot_tornado.py failed\n";
    return 1;
  }
  if (r.ok() && seq_s) j["paper"] = paper_figures_for(j, seq_s);
  return finish(r, std::move(j), o.report, o.image, o.depth, o.tl);
}

ZC_COMMAND("run", "simulate an algorithm on a machine model", cmd_run);

} // namespace zc::cli
