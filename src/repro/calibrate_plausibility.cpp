#include "repro/calibrate_plausibility.hpp"

#include "machine/cpu_model.hpp"
#include "machine/machine.hpp"

namespace zc::calibration {

nlohmann::json plausibility(const std::vector<double>& k) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& name : cpu_names()) {
    const CpuModel& cpu = cpu_model(name);
    CostTable phys = cpu.cycles, fit = scale_groups(cpu.cycles, k);
    const auto pf = phys.fields(), ff = fit.fields();
    for (std::size_t i = 0; i < pf.size(); ++i) {
      const double p = *pf[i].second, f = *ff[i].second;
      rows.push_back({{"cpu", name},
                      {"operation", pf[i].first.substr(5)},
                      {"physical_cycles", p},
                      {"fitted_cycles", f},
                      {"ratio", p > 0 ? f / p : 1.0}});
    }
  }
  return rows;
}

} // namespace zc::calibration
