#include "machine/machine_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>

#include <nlohmann/json.hpp>

#include "util/error.hpp"

namespace zc {

namespace {

using nlohmann::json;

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s;
}

// One object of the file, and the dotted path of its fields for the errors.
class Fields {
public:
  Fields(const std::string& file, const json& j, std::string prefix)
      : file_(file), j_(j), prefix_(std::move(prefix)) {
    if (!j_.is_object()) fail("", "expected an object {...}");
  }

  [[noreturn]] void fail(const std::string& key, const std::string& why) const {
    const std::string field = prefix_ + key;
    throw InputError(file_, 0, (field.empty() ? "" : "field '" + field + "': ") + why);
  }

  // Refuses a field not in `known` (a misspelt figure would otherwise be silently left out).
  void only(std::initializer_list<const char*> known) const {
    for (const auto& item : j_.items()) {
      const std::string& k = item.key();
      if (std::none_of(known.begin(), known.end(), [&](const char* n) { return k == n; }))
        fail(k, "unknown field");
    }
  }

  bool has(const char* key) const { return j_.contains(key); }

  const json& at(const char* key) const {
    if (!has(key)) fail(key, "missing");
    return j_.at(key);
  }

  std::string text(const char* key) const {
    const json& v = at(key);
    if (!v.is_string() || v.get<std::string>().empty()) fail(key, "expected a non-empty text");
    return v.get<std::string>();
  }

  Fields object(const char* key) const { return Fields(file_, at(key), prefix_ + key + "."); }

  // {"value": V, "source": "..."}: the value, after the source is checked to be there.
  const json& figure_value(const char* key) const {
    const Fields f = object(key);
    f.only({"value", "source"});
    f.text("source");
    return f.at("value");
  }

  double number(const char* key, bool positive = false) const {
    const json& v = figure_value(key);
    const std::string field = std::string(key) + ".value";
    if (!v.is_number()) fail(field, "expected a number");
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < 0 || (positive && x == 0))
      fail(field, positive ? "expected a finite number > 0" : "expected a finite number >= 0");
    return x;
  }

  std::string word(const char* key, const std::vector<std::string>& allowed) const {
    const json& v = figure_value(key);
    const std::string field = std::string(key) + ".value";
    const std::string w = v.is_string() ? v.get<std::string>() : "";
    if (std::find(allowed.begin(), allowed.end(), w) == allowed.end())
      fail(field, "expected one of " + joined(allowed));
    return w;
  }

private:
  const std::string& file_;
  const json& j_;
  std::string prefix_;
};

NetworkParams read_network(const Fields& n) {
  n.only({"switching", "startup_short_s", "startup_long_s", "short_max_bytes", "per_byte_s",
          "bandwidth_Bps", "both_ways_Bps", "per_hop_s", "host_startup_s", "host_per_byte_s"});
  NetworkParams p;
  const std::string sw = n.word("switching", {"circuit", "store-and-forward"});
  p.switching = sw == "circuit" ? Switching::Circuit : Switching::StoreAndForward;
  p.startup_short_s = n.number("startup_short_s");
  p.startup_long_s = n.number("startup_long_s");
  p.short_max_bytes = n.number("short_max_bytes");
  // The link's figure as its source gives it: seconds a byte, or bytes a second.
  if (n.has("per_byte_s") == n.has("bandwidth_Bps"))
    n.fail("per_byte_s", "give exactly one of per_byte_s and bandwidth_Bps");
  p.per_byte_s = n.has("per_byte_s") ? n.number("per_byte_s")
                                     : 1.0 / n.number("bandwidth_Bps", /*positive=*/true);
  if (n.has("both_ways_Bps")) p.both_ways_Bps = n.number("both_ways_Bps", /*positive=*/true);
  p.per_hop_s = n.number("per_hop_s");
  p.host_startup_s = n.number("host_startup_s");
  p.host_per_byte_s = n.number("host_per_byte_s");
  return p;
}

} // namespace

MachineSpec parse_machine_file(const std::string& path, const std::string& text,
                               const std::vector<std::string>& cpus) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(path, 0, std::string("not JSON: ") + e.what());
  }
  const Fields f(path, j, "");
  f.only({"name", "description", "docs", "cpu", "memory_bytes", "os_resident_bytes", "network"});
  MachineSpec m;
  m.name = f.text("name");
  if (m.name != std::filesystem::path(path).stem().string())
    f.fail("name", "'" + m.name + "' is not the file's name");
  m.description = f.text("description");
  f.text("docs"); // where the figures' ranges and confidence are discussed
  m.cpu = f.text("cpu");
  if (std::find(cpus.begin(), cpus.end(), m.cpu) == cpus.end())
    f.fail("cpu",
           "'" + m.cpu + "' is no CPU model (machines/cpu/): expected one of " + joined(cpus));
  m.memory_bytes = f.number("memory_bytes", /*positive=*/true);
  if (m.memory_bytes > kMaxNodeMemory_bytes) f.fail("memory_bytes.value", "above 1 PiB");
  m.os_resident_bytes = f.number("os_resident_bytes");
  if (m.os_resident_bytes >= m.memory_bytes)
    f.fail("os_resident_bytes.value", "leaves no memory to the program");
  m.net = read_network(f.object("network"));
  return m;
}

} // namespace zc
