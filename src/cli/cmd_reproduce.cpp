// zcube reproduce: the papers' tables and speed-up curves (repro/reproduce.hpp).
#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/paths.hpp"
#include "cli/sim_options.hpp"
#include "repro/papers.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"
#include "run/batch.hpp"
#ifdef ZCUBE_HAVE_MPI
#include <optional>

#include "mpi/mpi_session.hpp"
#include "mpi/sharded_batch.hpp"
#endif

namespace zc::cli {

static int cmd_reproduce(std::vector<std::string> args) {
  CLI::App app{"Reproduce the papers' tables and speed-up curves on the calibrated machines",
               "zcube reproduce"};
  ReproduceOptions o;
  o.root = source_root();
  o.out = "results";
  o.jobs = default_jobs();
  std::string which = "all";
  bool no_plots = false, no_calibration = false;
  std::vector<std::string> choices = paper_names_and_aliases();
  choices.push_back("all");
  app.add_option("paper", which, "a paper, or all of them and the fidelity table:" + papers_help())
      ->check(CLI::IsMember(choices))
      ->capture_default_str();
  app.add_option("--out", o.out, "output directory")->capture_default_str();
  [[maybe_unused]] auto* jobs_opt =
      app.add_option("--jobs", o.jobs,
                     "simulations at once, each its own process (per rank under mpirun: 1)")
          ->check(CLI::Range(1, 4096))
          ->capture_default_str();
  app.add_flag("--full", o.full,
               "Blazek's whole grid: 1..2048 spheres (about 8 minutes on two cores); the "
               "compositing study to 1024 nodes");
  app.add_flag("--overwrite", o.overwrite,
               "replace a paper's tables even when they hold more than this run writes (without "
               "it, such tables stay and this run's go beside them, e.g. results/blazek-quick/)");
  app.add_flag("--no-plots", no_plots, "skip the plots");
  app.add_option("--plot-format", o.plot_format, "png, svg or pdf")
      ->check(CLI::IsMember({"png", "svg", "pdf"}))
      ->capture_default_str();
  app.add_flag("--no-calibration", no_calibration,
               "skip the calibration's fit and validation (results/calibration/)");
  BatchSimGridFlags simgrid;
  simgrid.add_to(app);
  if (int rc = parse(app, args); rc >= 0) return rc;
  simgrid.apply();
  o.plots = !no_plots;
  o.calibration = !no_calibration;
  if (which != "all")
    o.papers = {find_paper(which)->name}; // an alias: the names docs/index.md uses
#ifdef ZCUBE_HAVE_MPI
  // Under mpirun: the simulations are shared among the ranks; rank 0 writes the results.
  std::optional<MpiSession> mpi;
  if (launched_by_mpirun()) {
    mpi.emplace();
    if (!jobs_opt->count()) o.jobs = 1;
    o.runner = [](const std::vector<RunConfig>& cfgs, int jobs,
                  const std::function<void(const BatchProgress&)>& progress) {
      return run_batch_sharded(cfgs, jobs, simulate_point, progress);
    };
    o.write = mpi->rank() == 0;
  }
#endif
  return reproduce(o);
}

ZC_COMMAND("reproduce", "reproduce the papers' tables and curves (the main job)", cmd_reproduce);

} // namespace zc::cli
