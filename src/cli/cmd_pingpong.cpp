// zcube pingpong: the classic message-passing benchmark, on a simulated machine.
#include <fstream>
#include <iomanip>
#include <iostream>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/paths.hpp"
#include "cli/sim_options.hpp"
#include "repro/provenance.hpp"
#include "repro/simulate.hpp"
#include "util/output_file.hpp"
#include "util/stdout_result.hpp"

namespace zc::cli {

static int cmd_pingpong(std::vector<std::string> args) {
  CLI::App app{"Ping-pong benchmark: virtual one-way time per message size and distance",
               "zcube pingpong"};
  SimFlags sf;
  sf.defaults["nodes"] = "2";
  sf.add_to(app);
  int from = 0;
  std::string to;
  std::string sizes = "0B,64B,100B,101B,1KiB,64KiB", report;
  app.add_option("--from", from, "sending node")->capture_default_str();
  app.add_option("--to", to, "answering node(s), comma-separated (default: every other node)");
  app.add_option("--sizes", sizes, "message sizes with units, comma-separated")
      ->capture_default_str();
  app.add_option("--report", report,
                 "write the report JSON (- or /dev/stdout: to standard output, the table to "
                 "standard error)");
  if (int rc = parse(app, args); rc >= 0) return rc;
  if (names_stdout(report))
    reserve_stdout_for_result();
  else
    check_output_path(report, "--report");
  RunConfig cfg;
  sf.apply(cfg);
  cfg.algorithm = "pingpong";
  cfg.compare_with_sequential = false;
  cfg.options.values = {{"from", std::to_string(from)}, {"sizes", sizes}};
  if (!to.empty()) cfg.options.values["to"] = to;
  const RunResult r = run_simulation(cfg);
  nlohmann::json j = report_with_paper_figures(r.report);
  j["provenance"] = provenance();
  if (!report.empty()) write_result_file(report, j.dump(2) + "\n");
  if (!r.ok()) {
    std::cerr << "zcube: error: " << r.error() << "\n";
    return 1;
  }
  const RunHeader& h = r.report.header;
  std::cout << "# " << h.machine << ", " << h.nodes << " nodes, " << h.topology << ", "
            << h.fidelity << "\n"
            << "# from  to  hops     bytes   one_way_us\n";
  const NodeRecord& sender = r.report.records.at(std::size_t(r.report.metrics_rank));
  for (const auto& x : sender.metrics.value("results", nlohmann::json::array()))
    std::cout << std::setw(6) << x["from"].get<int>() << std::setw(4) << x["to"].get<int>()
              << std::setw(6) << x["hops"].get<int>() << std::setw(10)
              << x["bytes"].get<std::uint64_t>() << std::setw(13) << std::fixed
              << std::setprecision(3) << x["one_way_s"].get<double>() * 1e6 << "\n";
  return 0;
}

ZC_COMMAND("pingpong", "communication benchmark on a simulated machine", cmd_pingpong);

} // namespace zc::cli
