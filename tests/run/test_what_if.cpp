// run/what_if and run/run_flags: the what-if descriptors (absolute and relative forms, bounds,
// how each edits a machine's figures) and the one flag table the commands are made from.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "machine/machine.hpp"
#include "run/run_flags.hpp"
#include "run/what_if.hpp"
#include "source_root.hpp"
#include "util/error.hpp"

using namespace zc;

namespace {

WhatIfValue parse(const std::string& flag, const std::string& text) {
  return parse_what_if(*find_what_if(flag), text);
}

MachineFigures edited(const std::string& machine, const std::map<std::string, std::string>& w) {
  WhatIfs what_ifs;
  for (const auto& [flag, text] : w)
    what_ifs.set(flag, parse(flag, text));
  MachineFigures f = machine_figures(machine_spec(machine), 2);
  apply_what_ifs(what_ifs, f);
  return f;
}

} // namespace

TEST(WhatIf, AbsoluteAndRelativeFormsParse) {
  const WhatIfValue abs = parse("latency", "275us");
  EXPECT_DOUBLE_EQ(abs.value, 275e-6);
  EXPECT_FALSE(abs.relative);
  EXPECT_EQ(parse("latency", "x0.1"), (WhatIfValue{0.1, true}));
  EXPECT_EQ(parse("latency", "x0"), (WhatIfValue{0, true})); // a start-up may vanish
  EXPECT_EQ(parse("bandwidth", "x4"), (WhatIfValue{4, true}));
  EXPECT_EQ(parse("memory", "x0.5"), (WhatIfValue{0.5, true}));
  // A factor flag is a factor in either form.
  EXPECT_EQ(parse("cpu-scale", "0.25"), (WhatIfValue{0.25, false}));
  EXPECT_EQ(parse("cpu-scale", "x0.25"), (WhatIfValue{0.25, false}));
}

TEST(WhatIf, MalformedValuesNameTheFlag) {
  for (const auto& [flag, text] : std::vector<std::pair<std::string, std::string>>{
           {"latency", "x"},
           {"latency", "x-1"},
           {"latency", "xabc"},
           {"latency", "x1e400"},
           {"latency", "275"}, // a bare number: no unit
           {"bandwidth", "x0"},
           {"memory", "x0"},
           {"cpu-scale", "x1e4"},
           {"latency", "2h"}}) {
    try {
      parse(flag, text);
      ADD_FAILURE() << flag << " " << text << " was accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--" + flag), std::string::npos) << e.what();
    }
  }
}

// The iPSC/860's two protocols (docs/machines.md): an absolute start-up replaces both, a factor
// scales each.
TEST(WhatIf, ARelativeLatencyKeepsEveryProtocol) {
  const NetworkParams own = machine_spec("ipsc860").net;
  ASSERT_NE(own.startup_short_s, own.startup_long_s);
  const auto rel = edited("ipsc860", {{"latency", "x0.1"}}).net;
  EXPECT_DOUBLE_EQ(rel.startup_short_s, 0.1 * own.startup_short_s);
  EXPECT_DOUBLE_EQ(rel.startup_long_s, 0.1 * own.startup_long_s);
  EXPECT_EQ(rel.per_byte_s, own.per_byte_s);
  const auto abs = edited("ipsc860", {{"latency", "7.5us"}}).net;
  EXPECT_DOUBLE_EQ(abs.startup_short_s, 7.5e-6);
  EXPECT_DOUBLE_EQ(abs.startup_long_s, 7.5e-6);
}

TEST(WhatIf, RelativeRatesMemoriesAndHopsScaleTheMachinesOwn) {
  const MachineSpec own = machine_spec("ipsc2");
  const auto f = edited("ipsc2", {{"bandwidth", "x4"},
                                  {"host-bandwidth", "x2"},
                                  {"host-latency", "x0.5"},
                                  {"per-hop", "x3"},
                                  {"memory", "x0.5"}});
  EXPECT_DOUBLE_EQ(f.net.per_byte_s, own.net.per_byte_s / 4);
  EXPECT_DOUBLE_EQ(f.net.host_per_byte_s, own.net.host_per_byte_s / 2);
  EXPECT_DOUBLE_EQ(f.net.host_startup_s, own.net.host_startup_s / 2);
  EXPECT_DOUBLE_EQ(f.net.per_hop_s, own.net.per_hop_s * 3);
  ASSERT_EQ(f.memory_bytes.size(), 2u);
  EXPECT_DOUBLE_EQ(f.memory_bytes[1], own.memory_bytes / 2);
  // The same figures as the absolute forms of those values.
  EXPECT_DOUBLE_EQ(edited("ipsc2", {{"bandwidth", "11.2MBps"}}).net.per_byte_s, f.net.per_byte_s);
}

TEST(WhatIf, AFactorThatLeavesTheBoundsIsAUsageErrorNamingTheFlag) {
  EXPECT_THROW(edited("ipsc2", {{"latency", "x1e8"}}), UsageError);    // 275 us x 1e8 > 1 h
  EXPECT_NO_THROW(edited("ipsc2", {{"latency", "x1e7"}}));             // 2750 s
  EXPECT_THROW(edited("ipsc2", {{"bandwidth", "x1e-7"}}), UsageError); // below 1 B/s
  try {
    edited("volvox", {{"per-hop", "x2"}});
    ADD_FAILURE() << "a per-hop cost on store-and-forward links";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("volvox is store-and-forward"), std::string::npos);
  }
}

TEST(WhatIf, CostScaleMultipliesWhatTheOthersSet) {
  const auto f = edited("ipsc2", {{"latency", "100us"}, {"cost-scale", "10"}, {"cpu-scale", "2"}});
  EXPECT_DOUBLE_EQ(f.net.startup_long_s, 1e-3);
  EXPECT_DOUBLE_EQ(f.cpu_factor, 20);
}

TEST(WhatIf, ReportColumnsAndComposition) {
  WhatIfs w;
  w.set("latency", {27.5e-6, false});
  w.set("bandwidth", {4, true});
  const auto c = what_if_columns(w);
  EXPECT_EQ(c.at("latency_s"), 27.5e-6);
  EXPECT_EQ(c.at("bandwidth_factor"), 4);
  EXPECT_EQ(c.size(), 2u);
  // regress --set latency=x2 on a run with its own 100 us: 200 us; on a run with x0.5: x1.
  EXPECT_EQ(compose_what_if({100e-6, false}, {2, true}), (WhatIfValue{200e-6, false}));
  EXPECT_EQ(compose_what_if({0.5, true}, {2, true}), (WhatIfValue{1, true}));
  EXPECT_EQ(compose_what_if({0.5, true}, {1e-3, false}), (WhatIfValue{1e-3, false}));
}

// Every what-if is a flag of the one table, in the same order, and the docs' flag table is the
// one the table prints.
TEST(RunFlags, EveryWhatIfIsOneFlagOfTheTable) {
  const auto& names = run_flag_names();
  std::size_t last = 0;
  for (const auto& w : what_if_specs()) {
    const auto it = std::find(names.begin(), names.end(), w.flag);
    ASSERT_NE(it, names.end()) << w.flag;
    EXPECT_GE(std::size_t(it - names.begin()), last) << w.flag;
    last = std::size_t(it - names.begin());
    EXPECT_EQ(find_run_flag(w.flag)->group, RunFlag::Group::WhatIf);
  }
  std::ifstream in(test::kRoot + "/docs/user-guide.md");
  std::stringstream doc;
  doc << in.rdbuf();
  EXPECT_NE(doc.str().find(run_flags_markdown()), std::string::npos)
      << "docs/user-guide.md's flag table differs from `zcube help flags`:\n"
      << run_flags_markdown();
}

TEST(RunFlags, DefaultsComeFromTheTable) {
  const RunConfig c = config_from_flags({}, "scene.json");
  EXPECT_EQ(c.machine, find_run_flag("machine")->default_text);
  EXPECT_EQ(c.nodes, std::stoi(find_run_flag("nodes")->default_text));
  EXPECT_EQ(c.algorithm, find_run_flag("algorithm")->default_text);
  EXPECT_EQ(c.options.frames, std::stoi(find_run_flag("frames")->default_text));
  EXPECT_EQ(c.scene_path, "scene.json");
  EXPECT_TRUE(c.what_ifs.empty());
  const RunConfig r = config_from_flags({{"latency", "x0.1"}, {"machine", "ipsc860"}}, "s");
  EXPECT_EQ(r.what_ifs.get("latency"), (WhatIfValue{0.1, true}));
}

TEST(WhatIf, RegressSetComposesOnTheRunsOwnText) {
  const WhatIfSpec& lat = *find_what_if("latency");
  EXPECT_DOUBLE_EQ(parse("latency", compose_what_if_text(lat, "100us", "x2")).value, 200e-6);
  EXPECT_EQ(compose_what_if_text(lat, "x0.5", "x2"), "x1");
  EXPECT_EQ(compose_what_if_text(lat, "100us", "1ms"), "1ms");
  EXPECT_EQ(compose_what_if_text(lat, "", "x2"), "x2");
  const WhatIfSpec& bw = *find_what_if("bandwidth");
  EXPECT_DOUBLE_EQ(parse("bandwidth", compose_what_if_text(bw, "2MBps", "x2")).value, 4e6);
  EXPECT_THROW(compose_what_if_text(lat, "100us", "x"), UsageError);
}
