// zcube compare: measured against predicted, phase by phase (repro/compare.hpp).
#include <iostream>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "repro/compare.hpp"

namespace zc::cli {

static int cmd_compare(std::vector<std::string> args) {
  CLI::App app{"Compare a measured report (run --backend mpi) with a predicted one (run --machine "
               "cluster.xml), phase by phase",
               "zcube compare"};
  std::string measured, predicted;
  app.add_option("--measured", measured, "report of the real run")->required();
  app.add_option("--predicted", predicted, "report of the simulation")->required();
  if (int rc = parse(app, args); rc >= 0) return rc;
  const auto m = read_report(measured), p = read_report(predicted);
  const Table t = compare_reports(m, p); // refuses mismatched reports before printing anything
  std::cout << m.value("algorithm", "?") << ", " << m.value("nodes", 0) << " nodes: "
            << (m.value("measured", false) ? "measured" : "simulated (not a measured report)")
            << " on " << m.value("machine", "?") << ", predicted on " << p.value("platform", "?")
            << " (" << p.value("fidelity", "?") << ")\n\n"
            << t.markdown();
  return 0;
}

ZC_COMMAND("compare", "measured against predicted times, phase by phase", cmd_compare);

} // namespace zc::cli
