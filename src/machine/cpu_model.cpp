#include "machine/cpu_model.hpp"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "machine/machine_data.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

const nlohmann::json& operations_json() {
  static const nlohmann::json j = nlohmann::json::parse(machine_data::kOperations);
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

CpuModel parse_cpu_json(const nlohmann::json& j) {
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

// A CPU data file, its errors one line naming the file (nlohmann's name the field).
CpuModel parse_cpu(const machine_data::DataFile& f) {
  CpuModel m;
  try {
    m = parse_cpu_json(nlohmann::json::parse(f.text));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(f.path, 0, e.what());
  }
  if (m.name != std::filesystem::path(f.path).stem().string())
    throw InputError(f.path, 0, "field 'name': '" + m.name + "' is not the file's name");
  return m;
}

// Every CPU built in (machines/cpu/*.json), in file name order.
const std::vector<CpuModel>& cpu_models() {
  static const std::vector<CpuModel> v = [] {
    std::vector<CpuModel> out;
    for (const auto& f : machine_data::cpu_files())
      out.push_back(parse_cpu(f));
    return out;
  }();
  return v;
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
  static const std::vector<std::string> n = [] {
    std::vector<std::string> out;
    for (const auto& m : cpu_models())
      out.push_back(m.name);
    return out;
  }();
  return n;
}

const CpuModel& cpu_model(const std::string& name) {
  for (const auto& m : cpu_models())
    if (m.name == name) return m;
  std::string names;
  for (const auto& n : cpu_names())
    names += (names.empty() ? "" : ", ") + n;
  throw UsageError("unknown CPU '" + name + "': expected one of " + names);
}

CostTable zcube_loop_seconds(const CpuModel& cpu) {
  return cpu.zcube_cycles.scaled(1.0 / cpu.clock_hz);
}

CostTable cpu_seconds(const CpuModel& cpu, const std::vector<double>& scale) {
  const CostTable s = cpu.cycles.scaled(1.0 / cpu.clock_hz);
  return scale.empty() ? s : scale_groups(s, scale);
}

} // namespace zc
