// run/report: the typed report written as JSON (report_json), without a simulation: the nodes'
// totals, the reporting node's metrics at the top level, the host computer's rank, the paper's
// timed region and the bands a later step adds.
#include <gtest/gtest.h>

#include "run/report.hpp"

using namespace zc;

namespace {

NodeRecord node(int rank, double busy, std::uint64_t sent, nlohmann::json metrics = {}) {
  NodeRecord r;
  r.who = Recorder::node(rank);
  r.stats.busy_s = busy;
  r.stats.bytes_sent = r.stats.payload_bytes_sent = sent;
  r.stats.messages = 1;
  r.phase_order = {"render"};
  r.phase_totals = {{"render", busy}};
  if (!metrics.is_null()) r.metrics = metrics;
  return r;
}

Report two_nodes() {
  Report r;
  r.header.nodes = 2;
  r.virtual_time_s = 3;
  r.records = {node(0, 1.0, 10, {{"results", "node 0's"}}),
               node(1, 2.0, 30, {{"results", "node 1's"}})};
  return r;
}

} // namespace

TEST(Report, TotalsAndPhasesComeFromTheNodes) {
  const nlohmann::json j = report_json(two_nodes());
  EXPECT_EQ(j["communication"]["messages"], 2);
  EXPECT_EQ(j["communication"]["bytes"], 40);
  EXPECT_EQ(j["communication"]["concurrent_volume_bytes"], 30);
  ASSERT_EQ(j["phases"].size(), 1u);
  EXPECT_EQ(j["phases"][0]["max_s"], 2.0);
  EXPECT_EQ(j["phases"][0]["mean_s"], 1.5);
  EXPECT_EQ(j["per_node"][1]["idle_s"], 1.0);
  EXPECT_DOUBLE_EQ(j["load_imbalance"].get<double>(), (2.0 - 1.0) / 1.5);
  EXPECT_FALSE(j.contains("timed_s")) << "no node started a timed region";
}

TEST(Report, TheReportingNodesMetricsAreTheRunsAndEveryNodeKeepsItsOwn) {
  Report r = two_nodes();
  EXPECT_EQ(report_json(r)["results"], "node 0's");
  r.metrics_rank = 1;
  const nlohmann::json j = report_json(r);
  EXPECT_EQ(j["results"], "node 1's");
  EXPECT_EQ(j["per_node"][0]["metrics"]["results"], "node 0's");
}

TEST(Report, TheHostComputerIsNamedAsOnThePlatform) {
  Report r = two_nodes();
  r.records.push_back(node(2, 0.5, 5));
  r.records.back().who = Recorder::host(2);
  const nlohmann::json j = report_json(r);
  EXPECT_EQ(j["per_node"][2]["rank"], "srm");
  EXPECT_EQ(j["communication"]["concurrent_volume_bytes"], 30) << "the nodes' only";
  // A record travels between processes (the MPI backend) and comes back the same.
  const NodeRecord back = nlohmann::json(r.records.back()).get<NodeRecord>();
  EXPECT_TRUE(back.who.host_computer);
  EXPECT_EQ(back.who.rank, 2);
}

TEST(Report, TimedRegionIsTheLongestOverTheNodesThatStartedOne) {
  Report r = two_nodes();
  r.records[0].stats.timed = true;
  r.records[0].stats.timed_start_s = 0.5;
  r.records[0].stats.finish_s = 2.5;
  r.records[1].stats.timed = true;
  r.records[1].stats.timed_start_s = 1.0;
  r.records[1].stats.timed_ended = true;
  r.records[1].stats.timed_end_s = 1.5;
  ASSERT_TRUE(timed_region_s(r).has_value());
  EXPECT_EQ(*timed_region_s(r), 2.0);
  EXPECT_EQ(report_json(r)["timed_s"], 2.0);
}

TEST(Report, BandsGoToTheirPhaseAndFailedRunsHaveAnEmptyImage) {
  Report r = two_nodes();
  r.phase_bands["render"] = {{"p05", 1.9}};
  r.bands = {{"method", "retimed"}};
  r.status = "out_of_memory";
  r.error = "node 1: out of memory";
  const nlohmann::json j = report_json(r);
  EXPECT_EQ(j["phases"][0]["bands"]["p05"], 1.9);
  EXPECT_EQ(j["bands"]["method"], "retimed");
  EXPECT_EQ(j["status"], "out_of_memory");
  EXPECT_EQ(j["error"], "node 1: out of memory");
  EXPECT_EQ(j["image"], nlohmann::json::object());
  EXPECT_FALSE(j.contains("model")) << "a measured or failed run without a machine says none";
}
