// zcube units: the units every quantity takes (flags and platform files), SimGrid's own tables
// (machine/units.hpp); --json for scripts (scripts/plot_results.py --units).
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "machine/units.hpp"

namespace zc::cli {

namespace {

struct Kind {
  const char* name;
  const char* base;
  const char* flags;
  const UnitTable& table;
};

void print_table(const Kind& k) {
  std::cout << k.name << " (base unit " << k.base << "; " << k.flags << "):\n ";
  int column = 1;
  for (const auto& [unit, factor] : k.table) {
    const std::string item = " " + unit + "=" + format_double(factor);
    if (column + item.size() > 100) {
      std::cout << "\n ";
      column = 1;
    }
    std::cout << item;
    column += int(item.size());
  }
  std::cout << "\n";
}

} // namespace

static int cmd_units(std::vector<std::string> args) {
  CLI::App app{"The units quantities take on the command line and in platform files: SimGrid's "
               "(a number, then the unit: 275us, 2.8MBps, 16MiB, 16Mf; flags require the unit)",
               "zcube units"};
  bool json = false;
  app.add_flag("--json", json, "the tables as JSON: {kind: {unit: factor to the base unit}}");
  if (int rc = parse(app, args); rc >= 0) return rc;
  const Kind kinds[] = {
      {"time", "s", "--latency, --per-hop, --host-latency; lat, latency", time_units()},
      {"bandwidth", "B/s", "--bandwidth, --host-bandwidth; bw, bandwidth", bandwidth_units()},
      {"size", "B", "--memory, pingpong --sizes; zcube.node_memory", size_units()},
      {"speed", "flop/s", "host speed", speed_units()}};
  if (json) {
    nlohmann::json j;
    for (const Kind& k : kinds)
      j[k.name] = k.table;
    std::cout << j.dump() << "\n";
    return 0;
  }
  for (const Kind& k : kinds)
    print_table(k);
  return 0;
}

ZC_COMMAND("units", "the units of times, rates, sizes and speeds (SimGrid's)", cmd_units);

} // namespace zc::cli
