// repro/reproduce_fidelity: results/fidelity.csv gives each network model's cost beside its
// error, a deterministic cost (the reports' simulation_cost) that the committed table states as a
// fresh run gives it and that grows with the fidelity.
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "csv.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"
#include "source_root.hpp"

using namespace zc;

namespace {

using test::kRoot;
using test::read_csv;

const char* const kCostColumns[] = {"messages", "flows", "network_events", "time_steps",
                                    "actor_switches"};

std::uint64_t count(const std::map<std::string, std::string>& row, const std::string& column) {
  const std::string& cell = row.at(column);
  EXPECT_FALSE(cell.empty()) << row.at("run") << " " << row.at("fidelity") << " " << column;
  EXPECT_EQ(cell.find_first_not_of("0123456789"), std::string::npos) << column << ": " << cell;
  return cell.empty() ? 0 : std::stoull(cell);
}

// (run, fidelity) -> row of the committed table.
std::map<std::pair<std::string, std::string>, std::map<std::string, std::string>> committed() {
  std::map<std::pair<std::string, std::string>, std::map<std::string, std::string>> by;
  for (const auto& row : read_csv(kRoot + "/results/fidelity.csv"))
    by[{row.at("run"), row.at("fidelity")}] = row;
  return by;
}

} // namespace

// Every row has the cost columns, and in every run flow solves SimGrid transfers (one per message
// that carries bytes to another node) where analytic and circuit solve none, and flow and circuit
// (the network's actor) switch actors more than analytic.
TEST(ReproduceFidelity, CostColumnsGrowWithFidelity) {
  const auto rows = committed();
  ASSERT_FALSE(rows.empty());
  int runs = 0;
  for (const auto& [key, row] : rows) {
    for (const char* c : kCostColumns)
      ASSERT_TRUE(row.count(c)) << "fidelity.csv has no column " << c;
    if (key.second != "analytic") continue;
    ++runs;
    SCOPED_TRACE(key.first);
    const auto& flow = rows.at({key.first, "flow"});
    const auto& circuit = rows.at({key.first, "circuit"});
    const auto messages = count(row, "messages");
    EXPECT_EQ(count(flow, "messages"), messages);
    EXPECT_EQ(count(circuit, "messages"), messages);
    EXPECT_EQ(count(row, "flows"), 0u);
    EXPECT_GT(count(flow, "flows"), 0u);
    EXPECT_LE(count(flow, "flows"), messages * std::stoull(row.at("nodes"))); // one a hop at most
    EXPECT_EQ(count(circuit, "flows"), 0u);
    EXPECT_GT(count(flow, "time_steps"), count(row, "time_steps"));
    EXPECT_GT(count(flow, "actor_switches"), count(row, "actor_switches"));
    EXPECT_GT(count(circuit, "actor_switches"), count(row, "actor_switches"));
  }
  EXPECT_GE(runs, 10);
}

// The committed cost is what the reports of a fresh simulation say, for one run under the three
// fidelities (as reproduce runs them: one recorded, the others replayed), twice.
TEST(ReproduceFidelity, CommittedCostIsCurrentAndTheSameTwice) {
  ReproduceOptions o;
  o.root = kRoot;
  const std::string run = "elastic-teapot-ipsc860-16";
  std::vector<RunConfig> cfgs;
  std::vector<std::string> fidelities;
  for (const auto& pt : fidelity_plan(o).points)
    if (pt.key.starts_with(run + "/")) {
      cfgs.push_back(pt.cfg);
      fidelities.push_back(pt.key.substr(run.size() + 1));
    }
  ASSERT_EQ(cfgs.size(), 3u);
  const auto first = simulate_batch(cfgs, 2), second = simulate_batch(cfgs, 2);
  const auto rows = committed();
  for (std::size_t i = 0; i < cfgs.size(); ++i) {
    SCOPED_TRACE(fidelities[i]);
    ASSERT_EQ(first[i]["status"], "ok") << first[i].dump().substr(0, 400);
    EXPECT_EQ(first[i]["simulation_cost"], second[i]["simulation_cost"]);
    const auto& row = rows.at({run, fidelities[i]});
    EXPECT_EQ(count(row, "messages"), first[i]["communication"]["messages"].get<std::uint64_t>());
    for (const char* c : kCostColumns)
      if (std::string(c) != "messages") {
        EXPECT_EQ(count(row, c), first[i]["simulation_cost"][c].get<std::uint64_t>()) << c;
      }
  }
}
