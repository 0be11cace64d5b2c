#include "machine/cpu_model.hpp"

#include <nlohmann/json.hpp>

#include "machine/cpu_data.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

const nlohmann::json& operations_json() {
  static const nlohmann::json j = nlohmann::json::parse(cpu_data::kOperations);
  return j;
}

double mix_cycles(const std::map<std::string, double>& mix, const CpuModel& cpu) {
  double c = 0;
  for (const auto& [cls, count] : mix) {
    auto it = cpu.classes.find(cls);
    if (it == cpu.classes.end())
      throw std::logic_error("machines/cpu/" + cpu.name + ".json: no instruction class '" + cls +
                             "'");
    c += count * it->second.cycles;
  }
  return c;
}

CpuModel parse_cpu(const char* text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  CpuModel m;
  m.name = j.at("name");
  m.description = j.at("description");
  m.clock_hz = j.at("clock_hz");
  for (const auto& [k, v] : j.at("sources").items())
    m.sources[k] = v.get<std::string>();
  for (const auto& [k, v] : j.at("cycles").items())
    m.classes[k] = {v.at("cycles").get<double>(), v.at("why").get<std::string>(),
                    v.at("source").get<std::string>()};
  std::map<std::string, const OperationMix*> per_field;
  for (const auto& op : operation_mixes())
    per_field[op.field] = &op;
  auto zcube = m.zcube_cycles.fields();
  auto cycles = m.cycles.fields();
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    const OperationMix& op = *per_field.at(cycles[i].first.substr(5)); // "cost_<field>"
    *zcube[i].second = mix_cycles(op.mix, m);
    *cycles[i].second = op.zcube_only ? 0 : *zcube[i].second;
  }
  return m;
}

} // namespace

const std::vector<OperationMix>& operation_mixes() {
  static const std::vector<OperationMix> v = [] {
    std::vector<OperationMix> out;
    const auto& ops = operations_json().at("operations");
    CostTable order;
    for (auto& [id, ignored] : order.fields()) {
      const std::string f = id.substr(5);
      const auto& o = ops.at(f);
      OperationMix m{f, o.at("does").get<std::string>(), {}, o.value("zcube_only", false)};
      for (const auto& [cls, n] : o.at("mix").items())
        m.mix[cls] = n.get<double>();
      out.push_back(m);
    }
    return out;
  }();
  return v;
}

double plausible_low() {
  return operations_json().at("range")[0].get<double>();
}
double plausible_high() {
  return operations_json().at("range")[1].get<double>();
}

const std::vector<std::string>& cpu_names() {
  static const std::vector<std::string> n = {"i80386", "i860xr"};
  return n;
}

const CpuModel& cpu_model(const std::string& name) {
  static const CpuModel i386 = parse_cpu(cpu_data::kI80386);
  static const CpuModel i860 = parse_cpu(cpu_data::kI860XR);
  if (name == "i80386") return i386;
  if (name == "i860xr") return i860;
  throw UsageError("unknown CPU '" + name + "': expected i80386 or i860xr");
}

CostTable zcube_loop_seconds(const CpuModel& cpu) {
  return cpu.zcube_cycles.scaled(1.0 / cpu.clock_hz);
}

CostTable cpu_seconds(const CpuModel& cpu, const std::vector<double>& scale) {
  const CostTable s = cpu.cycles.scaled(1.0 / cpu.clock_hz);
  return scale.empty() ? s : scale_groups(s, scale);
}

} // namespace zc
