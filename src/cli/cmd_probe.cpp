// zcube probe: measure the cluster under mpirun and write its platform file (mpi/probe.hpp).
#include <iomanip>
#include <iostream>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "cli/paths.hpp"
#include "repro/sweep.hpp"
#include "util/error.hpp"
#include "util/output_file.hpp"
#ifdef ZCUBE_HAVE_MPI
#include "mpi/mpi_session.hpp"
#include "mpi/probe.hpp"
#endif

namespace zc::cli {

// The most a CPU loop of the probe is timed for (--seconds): each of its ~40 loops is timed for
// that long, three rounds, alone and at once, so 60 s already makes a probe of hours.
constexpr double kMaxProbeSeconds = 60;

static int cmd_probe(std::vector<std::string> args) {
  CLI::App app{"Measure the MPI processes' network and CPU and write a platform of them "
               "(mpirun -np P zcube probe --out cluster.xml)",
               "zcube probe"};
  std::string out = "cluster.xml", json;
  double seconds = 0.2;
  app.add_option("--out", out, "platform XML to write")->capture_default_str();
  app.add_option("--json", json, "also write the measurements as JSON");
  std::string nodes;
  app.add_option("--nodes", nodes,
                 "write platforms for these node counts (comma-separated; default: the ranks)");
  app.add_option("--seconds", seconds, "least time per CPU measurement")->capture_default_str();
  if (int rc = parse(app, args); rc >= 0) return rc;
#ifdef ZCUBE_HAVE_MPI
  ProbeOptions o;
  o.root = source_root();
  o.out = out;
  o.seconds = seconds;
  if (!nodes.empty())
    for (const auto& v : split_list(nodes, "nodes")) {
      try {
        o.nodes.push_back(std::stoi(v));
      } catch (const std::exception&) {
        throw UsageError("--nodes '" + v + "': expected a node count");
      }
    }
  // Checked before the measurements (tens of seconds): the least time a loop is timed, and every
  // file the probe will write.
  if (!(seconds > 0 && seconds <= kMaxProbeSeconds))
    throw UsageError("--seconds: expected a time above 0 and at most " +
                     std::to_string(int(kMaxProbeSeconds)) + " s");
  std::vector<std::pair<std::string, std::string>> outputs{{"--json", json}};
  for (const auto& f : probe_outputs(o, 0))
    outputs.push_back({"--out", f});
  check_output_paths(outputs);
  MpiSession mpi;
  const auto m = probe_cluster(o);
  if (mpi.rank() != 0) return 0;
  if (!json.empty()) write_text_file(json, m.dump(1) + "\n");
  const auto& n = m["network"];
  std::cout << std::setprecision(4) << "network: start-up "
            << n["startup_short_s"].get<double>() * 1e6 << " us (short), "
            << n["startup_long_s"].get<double>() * 1e6 << " us (long), "
            << 1e-6 / std::max(n["per_byte_s"].get<double>(), 1e-300) << " MB/s, both ways "
            << n["both_ways_Bps"].get<double>() * 1e-6 << " MB/s in all (0: no limit)\n";
  auto cpu = [&](const char* what, const nlohmann::json& c) {
    std::cout << what << " (ns): vertex " << c["cost_vertices_transformed"].get<double>() * 1e9
              << ", triangle set-up " << c["cost_triangles_setup"].get<double>() * 1e9 << ", span "
              << c["cost_spans"].get<double>() * 1e9 << ", fragment "
              << c["cost_pixels_generated"].get<double>() * 1e9 << ", merge "
              << c["cost_merge_ops"].get<double>() * 1e9 << ", byte copied "
              << c["cost_bytes_packed"].get<double>() * 1e9 << "\n";
  };
  cpu("CPU, one rank alone (one node)", m["cost_alone"]);
  cpu("CPU, every rank at once (several nodes)", m["cost"]);
  for (const auto& p : m["platforms"])
    std::cout << "wrote " << p["file"].get<std::string>() << " (" << p["nodes"] << " nodes, "
              << p["topology"].get<std::string>() << "): zcube run --machine "
              << p["file"].get<std::string>() << " --fidelity analytic ...\n";
  return 0;
#else
  (void)out;
  (void)nodes;
  throw UsageError("probe: this zcube was built without MPI (scripts/setup.sh installs "
                   "libopenmpi-dev; then rebuild)");
#endif
}

ZC_COMMAND("probe", "measure an MPI cluster and write its platform file", cmd_probe);

} // namespace zc::cli
