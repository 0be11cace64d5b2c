// zcube calibrate: fit the CPU cost tables to the seeds' figures (repro/calibrate.hpp).
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/paths.hpp"
#include "cli/sim_options.hpp"
#include "machine/machine.hpp"
#include "repro/calibrate.hpp"
#include "run/batch.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

namespace zc::cli {

static int cmd_calibrate(std::vector<std::string> args) {
  CLI::App app{"Bound the physical CPU cost estimates by Kurc et al. Table 2 (iPSC/2) and validate "
               "them (leave-one-scene-out, Charles et al.'s iPSC/860 speed-ups as predictions)",
               "zcube calibrate"};
  CalibrationOptions o;
  o.root = source_root();
  o.jobs = default_jobs();
  // Installed: the working directory, never the install prefix.
  std::string out = installed_data() ? "zcube-calibration" : o.root + "/results/calibration";
  bool write = false, no_crossval = false, overwrite = false;
  app.add_option("--jobs", o.jobs, "simulations at once")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  app.add_option("--out", out, "directory for fit.json, the CSV tables and README.md")
      ->capture_default_str();
  app.add_option("--max-iterations", o.max_iterations, "fixed-point steps of the iPSC/2 fit")
      ->capture_default_str();
  app.add_option("--fix", o.fixed_groups,
                 "cost groups kept at their physical estimate (default: the last --select choice)");
  app.add_flag("--no-crossval", no_crossval, "skip the leave-one-scene-out folds");
  app.add_flag("--select", o.select,
               "choose the groups kept physical by cross-validating every candidate set "
               "(about five times longer)");
  app.add_flag("--write", write, "also rewrite src/machine/calibrated_costs.hpp (then rebuild)");
  app.add_flag("--overwrite", overwrite,
               "replace the fit.json already in --out (the committed results/calibration/)");
  BatchSimGridFlags simgrid;
  simgrid.add_to(app);
  if (int rc = parse(app, args); rc >= 0) return rc;
  simgrid.apply();
  o.cross_validate = !no_crossval;
  // Checked before the fit (minutes), not found wanting after it.
  if (o.max_iterations < 1)
    throw UsageError("--max-iterations " + std::to_string(o.max_iterations) +
                     ": expected at least 1 fixed-point step");
  for (const auto& g : o.fixed_groups) {
    std::string names;
    bool known = false;
    for (const auto& cg : cost_groups()) {
      names += (names.empty() ? "" : ", ") + cg.name;
      known = known || cg.name == g;
    }
    if (!known) throw UsageError("--fix " + g + ": not a cost group (" + names + ")");
  }
  // Checked before the fit (minutes): a calibration is never replaced without being told.
  if (std::filesystem::exists(out + "/fit.json") && !overwrite)
    throw UsageError("--out " + out +
                     ": holds a calibration (fit.json); give another --out or "
                     "--overwrite to replace it");
  if (std::filesystem::exists(out) && !std::filesystem::is_directory(out))
    throw UsageError("--out " + out + ": exists and is not a directory");
  const nlohmann::json fit = calibrate(o);
  write_calibration_results(fit, out);
  std::cout << std::setprecision(4) << "multipliers of the physical estimates:";
  for (std::size_t g = 0; g < fit["scale"].size(); ++g)
    std::cout << " " << fit["groups"][g]["name"].get<std::string>() << " "
              << fit["scale"][g].get<double>() << (fit["at_bound"][g].get<bool>() ? "*" : "");
  std::cout << " (* on a bound)\nrms relative error, Kurc Table 2: "
            << fit["rms_rel_error"]["kurc_prior"] << " -> " << fit["rms_rel_error"]["kurc_fitted"]
            << "\n";
  if (fit.contains("crossval"))
    std::cout << "leave-one-scene-out median |error|: " << fit["crossval"]["median_abs_rel_error"]
              << "\n";
  for (const auto& c : fit["charles"])
    std::cout << "Charles teapot on " << c["nodes"] << " nodes: predicted speed-up "
              << c["predicted"].get<double>() << " (paper " << c["paper"] << ")\n";
  std::cout << "wrote " << out << "/\n";
  if (write) {
    const std::string h = o.root + "/src/machine/calibrated_costs.hpp";
    write_text_file(h, calibrated_costs_header(fit));
    std::cout << "wrote " << h << ": rebuild\n";
  }
  return 0;
}

ZC_COMMAND("calibrate", "fit the CPU cost tables to the papers' figures", cmd_calibrate);

} // namespace zc::cli
