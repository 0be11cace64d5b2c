// zcube calibrate: fit the CPU cost tables to the seeds' figures (repro/calibrate.hpp).
#include <fstream>
#include <iomanip>
#include <iostream>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/paths.hpp"
#include "repro/calibrate.hpp"
#include "sim/batch.hpp"

namespace zc::cli {

static int cmd_calibrate(std::vector<std::string> args) {
  CLI::App app{"Fit the CPU cost tables to Kurc et al. Table 2 (iPSC/2) and Charles et al.'s "
               "teapot speed-ups (i860)",
               "zcube calibrate"};
  CalibrationOptions o;
  o.root = source_root();
  o.jobs = default_jobs();
  std::string out = o.root + "/results/calibration";
  bool write = false;
  app.add_option("--jobs", o.jobs, "simulations at once")->capture_default_str();
  app.add_option("--out", out, "directory for fit.json, targets.csv, README.md")
      ->capture_default_str();
  app.add_option("--max-iterations", o.max_iterations, "fixed-point steps of the iPSC/2 fit")
      ->capture_default_str();
  app.add_option("--fix", o.fixed_groups, "cost groups kept at the prior (e.g. packing)");
  app.add_flag("--write", write,
               "also rewrite src/machine/calibrated_costs.hpp (then rebuild and run "
               "scripts/gen_platforms.sh)");
  if (int rc = parse(app, args); rc >= 0) return rc;
  const nlohmann::json fit = calibrate(o);
  write_calibration_results(fit, out);
  std::cout << std::setprecision(4) << "iPSC/2 group multipliers:";
  for (std::size_t g = 0; g < fit["i386_scale"].size(); ++g)
    std::cout << " " << fit["groups"][g]["name"].get<std::string>() << " "
              << fit["i386_scale"][g].get<double>();
  std::cout << "\ni860 speed ratio over the 80386: " << fit["i860_ratio"].get<double>() << "\n"
            << "rms relative error, Kurc Table 2: " << fit["rms_rel_error"]["kurc_prior"] << " -> "
            << fit["rms_rel_error"]["kurc_fitted"]
            << "; Charles speed-ups: " << fit["rms_rel_error"]["charles_prior"] << " -> "
            << fit["rms_rel_error"]["charles_fitted"] << "\nwrote " << out << "/\n";
  if (write) {
    const std::string h = o.root + "/src/machine/calibrated_costs.hpp";
    std::ofstream(h) << calibrated_costs_header(fit);
    std::cout << "wrote " << h << ": rebuild, then scripts/gen_platforms.sh\n";
  }
  return 0;
}

ZC_COMMAND("calibrate", "fit the CPU cost tables to the papers' figures", cmd_calibrate);

} // namespace zc::cli
