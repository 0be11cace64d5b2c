// Helpers shared by the reproduction plans.
#include "repro/reproduce.hpp"

namespace zc {

SimConfig repro_config(const std::string& machine, int nodes, const std::string& algorithm,
                       const std::string& scene, int size) {
  SimConfig c;
  c.machine = machine;
  c.nodes = nodes;
  c.algorithm = algorithm;
  c.scene_path = scene;
  c.width = c.height = size;
  return c;
}

bool ok(const nlohmann::json& r) {
  return r.value("status", "") == "ok";
}

bool out_of_memory(const nlohmann::json& r) {
  return r.value("status", "") == "out_of_memory";
}

double virtual_s(const nlohmann::json& r) {
  return r.value("virtual_time_s", 0.0);
}

} // namespace zc
