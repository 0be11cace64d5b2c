// zcube regress: the standard runs against golden reports, or two report directories against each
// other (repro/regress.hpp).
#include <iostream>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/paths.hpp"
#include "cli/sim_options.hpp"
#include "repro/regress.hpp"
#include "repro/table.hpp"
#include "run/batch.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"

namespace zc::cli {

static int cmd_regress(std::vector<std::string> args) {
  CLI::App app{"Compare the simulated timings and images of the standard runs with golden reports",
               "zcube regress"};
  const std::string root = source_root();
  std::string against, with, write, runs_file = root + "/tests/golden/runs.json";
  std::vector<std::string> sets;
  int jobs = default_jobs();
  double rtol = 1e-9;
  app.add_option("--against", against, "directory of reduced reports to compare with");
  app.add_option("--with", with,
                 "compare --against with this directory instead of running (two versions or two "
                 "platform files, each written by --write)");
  app.add_option("--write", write, "write the reduced reports of this run to a directory");
  app.add_option("--runs", runs_file, "runs file")->capture_default_str();
  app.add_option("--set", sets, "override a flag in every run: flag=value (e.g. latency=10us)");
  app.add_option("--jobs", jobs, "runs at once")->check(CLI::Range(1, 4096))->capture_default_str();
  app.add_option("--rtol", rtol,
                 "numbers within this relative difference are equal (0: bit for bit)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  BatchSimGridFlags simgrid;
  simgrid.add_to(app);
  if (int rc = parse(app, args); rc >= 0) return rc;
  simgrid.apply();
  against = data_file(against); // tests/golden: the golden runs installed with the binary
  if (against.empty() && write.empty())
    throw UsageError("regress: give --against DIR (compare) and/or --write DIR (record)");
  if (!with.empty() && against.empty()) throw UsageError("regress: --with needs --against");

  // Every input read and every output checked before any run (16 simulations).
  const auto before =
      against.empty() ? std::map<std::string, nlohmann::json>{} : read_report_dir(against);
  if (!write.empty()) prepare_output_dir(write, "--write");
  std::map<std::string, nlohmann::json> now;
  if (!with.empty()) {
    now = read_report_dir(with);
  } else {
    std::map<std::string, std::string> set;
    for (const auto& s : sets) {
      const auto eq = s.find('=');
      if (eq == std::string::npos || eq == 0)
        throw UsageError("--set '" + s + "': expected flag=value");
      set[s.substr(0, eq)] = s.substr(eq + 1);
    }
    now = run_regress(read_regress_runs(runs_file), root, jobs, set);
  }
  if (!write.empty()) {
    write_report_dir(now, write);
    std::cout << "regress: wrote " << now.size() << " reports to " << write << "/\n";
  }
  // A run that failed is never a success, even when the golden report failed the same way.
  const auto failed = failed_runs(now);
  for (const auto& f : failed)
    std::cerr << "regress: run " << f << "\n";
  if (against.empty()) return failed.empty() ? 0 : 1;
  const auto diffs = compare_reduced(before, now, rtol);
  if (diffs.empty()) {
    std::cout << "regress: " << now.size() << " runs, identical to " << against
              << (rtol > 0 ? " (relative tolerance " + num(rtol) + ")" : " (bit for bit)") << "\n";
    return failed.empty() ? 0 : 1;
  }
  Table t{{"run", "quantity", against, with.empty() ? "now" : with, "relative change"}, {}};
  for (const auto& d : diffs)
    t.add({d.run, d.quantity, d.before, d.after, d.rel != 0 ? num(d.rel, 3) : ""});
  std::cout << t.markdown() << "regress: " << diffs.size() << " differences"
            << (failed.empty() ? "" : ", " + std::to_string(failed.size()) + " runs failed")
            << "\n";
  return 1;
}

ZC_COMMAND("regress", "compare simulated timings and images with golden reports", cmd_regress);

} // namespace zc::cli
