#include "repro/calibrate_runs.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "machine/platform_xml.hpp"
#include "repro/simulate.hpp"

namespace zc::calibration {

TempPlatform::TempPlatform(const std::string& machine, const CostTable& cost, int nodes) {
  MachineSpec spec = machine_spec(machine);
  spec.cost = cost;
  static int serial = 0;
  path_ = (std::filesystem::temp_directory_path() /
           ("zcube-calibrate-" + std::to_string(getpid()) + "-" + std::to_string(serial++) + "-" +
            platform_file_name(machine, nodes, Topology::Cube)))
              .string();
  text_ = platform_xml(spec, nodes, Topology::Cube);
  std::ofstream(path_) << text_;
}

TempPlatform::~TempPlatform() {
  std::filesystem::remove(path_);
}

std::vector<nlohmann::json> run_all(const std::vector<RunConfig>& cfgs,
                                    const CalibrationOptions& o) {
  auto reps = simulate_batch(cfgs, o.jobs, {}, true); // its later steps replay the first's
  for (std::size_t i = 0; i < reps.size(); ++i)
    if (reps[i].value("status", "") != "ok")
      throw std::runtime_error("calibration run " + cfgs[i].algorithm + " on " +
                               cfgs[i].scene_path + " failed: " + reps[i].value("error", "?"));
  return reps;
}

double rms(const std::vector<double>& e) {
  double s = 0;
  for (double x : e)
    s += x * x;
  return e.empty() ? 0 : std::sqrt(s / double(e.size()));
}

double median_abs(std::vector<double> e) {
  for (double& x : e)
    x = std::fabs(x);
  std::sort(e.begin(), e.end());
  if (e.empty()) return 0;
  const std::size_t n = e.size();
  return n % 2 ? e[n / 2] : 0.5 * (e[n / 2 - 1] + e[n / 2]);
}

} // namespace zc::calibration
