// Bands and sensitivities (sim/bands.hpp, docs/uncertainty.md): the retimer gives the simulated
// run's own figures, bands are ordered and hold the point prediction, a what-if difference priced
// by paired draws is narrower than its two bands together, and elasticities match closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "run/batch.hpp"
#include "sim/bands.hpp"
#include "sim_fixtures.hpp"
#include "source_root.hpp"

using namespace zc;
using namespace zc::test;

namespace {

nlohmann::json run_banded(const RunConfig& cfg, const BandsRequest& req) {
  const auto r = run_batch(
      {cfg}, 1, [&](const RunConfig& c) { return report_json(run_with_bands(c, req).report); });
  EXPECT_EQ(r.front()["status"], "ok") << r.front().dump().substr(0, 400);
  return r.front();
}

RunConfig paper_run(const std::string& machine, int nodes, const std::string& algorithm,
                    const std::string& scene, int size, Topology topo = Topology::Cube) {
  RunConfig c;
  c.machine = machine;
  c.nodes = nodes;
  c.topology = topo;
  c.algorithm = algorithm;
  c.scene_path = kRoot + "/" + scene;
  c.width = c.height = size;
  c.compare_with_sequential = false;
  return c;
}

void expect_band_holds(const nlohmann::json& band, double point, const std::string& what) {
  const double p05 = band.at("p05"), p50 = band.at("p50"), p95 = band.at("p95");
  EXPECT_LE(p05, p50) << what;
  EXPECT_LE(p50, p95) << what;
  EXPECT_LE(p05, point) << what;
  EXPECT_GE(p95, point) << what;
  EXPECT_NEAR(p50 / point, 1.0, 0.03) << what << ": p50 " << p50 << ", point " << point;
}

const BandsRequest kDraws{.draws = 200, .seed = 7, .sensitivity = true};

} // namespace

// Every draw is priced by retiming, which must first give the simulated run's figures to the
// bit; Kurc's schemes (circuit contention), Charles's ring and Blazek's host computer.
TEST(Bands, RetimedRunsAgreeWithTheSimulationAndHoldThePoint) {
  const RunConfig runs[] = {
      paper_run("ipsc2", 16, "pair-rs", "scenes/kurc/2pot.json", 200),
      paper_run("ipsc2", 8, "aapc-hbp", "scenes/kurc/1pot.json", 160),
      paper_run("ipsc860", 8, "elastic", "scenes/bone.json", 128, Topology::Ring),
      paper_run("ipsc2", 4, "host-initiated", "scenes/blazek/thesis_spheres_1.json", 64)};
  for (const RunConfig& c : runs) {
    const auto r = run_banded(c, kDraws);
    ASSERT_TRUE(r.contains("bands")) << c.algorithm;
    const auto& b = r["bands"];
    ASSERT_EQ(b["method"], "retimed") << c.algorithm << ": " << b.dump();
    EXPECT_EQ(b["agreement_rel"].get<double>(), 0.0) << c.algorithm;
    EXPECT_EQ(b["values"]["virtual_time_s"].size(), 200u) << c.algorithm;
    expect_band_holds(b["virtual_time_s"], r["virtual_time_s"], c.algorithm + " virtual time");
    if (r.contains("timed_s"))
      expect_band_holds(b["timed_s"], r["timed_s"], c.algorithm + " timed region");
    ASSERT_FALSE(r["phases"].empty()) << c.algorithm;
    for (const auto& p : r["phases"]) {
      if (p["max_s"].get<double>() <= 0) continue;
      ASSERT_TRUE(p.contains("bands")) << c.algorithm << " " << p["name"];
      expect_band_holds(p["bands"], p["max_s"], c.algorithm + " " + p["name"].get<std::string>());
    }
  }
}

// The same draws price both runs, so the band of ten times lower latency's gain is the band of
// the difference, narrower than the two runs' bands together.
TEST(Bands, WhatIfDifferenceIsNarrowerThanTheSumOfItsBands) {
  RunConfig base = paper_run("ipsc2", 16, "pair-rs", "scenes/kurc/2pot.json", 200);
  RunConfig fast = base;
  fast.what_ifs.set("latency", {27.5e-6});
  const BandsRequest req{.draws = 200, .seed = 3};
  const auto a = run_banded(base, req), b = run_banded(fast, req);
  const auto& va = a["bands"]["values"]["timed_s"];
  const auto& vb = b["bands"]["values"]["timed_s"];
  ASSERT_EQ(va.size(), 200u);
  ASSERT_EQ(vb.size(), 200u);
  std::vector<double> diff;
  for (std::size_t i = 0; i < va.size(); ++i)
    diff.push_back(va[i].get<double>() - vb[i].get<double>());
  const auto width = [](const nlohmann::json& band) {
    return band["p95"].get<double>() - band["p05"].get<double>();
  };
  const double diff_width = quantile(diff, 0.95) - quantile(diff, 0.05);
  EXPECT_GT(quantile(diff, 0.05), 0) << "lower latency always gains";
  EXPECT_LT(diff_width, 0.5 * (width(a["bands"]["timed_s"]) + width(b["bands"]["timed_s"])));
}

// A run without the host computer does not depend on its link: elasticity 0 exactly.
TEST(Bands, UnusedParameterHasZeroElasticity) {
  const auto r = run_banded(paper_run("ipsc2", 8, "pair-rs", "scenes/kurc/1pot.json", 128),
                            {.sensitivity = true});
  const auto& s = r["sensitivity"];
  ASSERT_EQ(s["method"], "retimed") << s.dump();
  EXPECT_EQ(s["timed_s"]["host_startup"].get<double>(), 0.0);
  EXPECT_EQ(s["timed_s"]["host_per_byte"].get<double>(), 0.0);
  EXPECT_GT(s["timed_s"]["cpu.geometry"].get<double>(), 0.05);
}

// One message to a neighbour, timed from its send to its receipt: T = start-up + m x per-byte,
// so the elasticities against the two are their shares of T and sum to 1.
TEST(Bands, OneWayMessageElasticitiesSumToOne) {
  for (double bytes : {64.0, 4096.0, 200000.0}) {
    RunConfig cfg = sim_config("ipsc2", 2, Topology::Cube, Fidelity::Circuit);
    auto a = std::make_shared<Algorithm>();
    a->name = "one-way";
    a->node = [bytes](NodeContext& ctx) {
      Comm& c = ctx.comm();
      ctx.start_timed_region();
      if (c.rank() == 0)
        c.send(1, 0, Bytes(std::size_t(bytes)));
      else
        c.recv(0, 0);
      ctx.end_timed_region();
    };
    cfg.custom = a;
    const auto r = run_banded(cfg, {.sensitivity = true});
    const auto& e = r["sensitivity"]["timed_s"];
    ASSERT_TRUE(e.contains("startup")) << r["sensitivity"].dump();
    const double sum = e["startup"].get<double>() + e["per_byte"].get<double>();
    EXPECT_NEAR(sum, 1.0, 0.01) << bytes << " bytes";
    const auto& net = r["model"];
    const double T = net["startup_short_s"].get<double>() * (bytes <= 100) +
                     net["startup_long_s"].get<double>() * (bytes > 100) +
                     bytes * net["per_byte_s"].get<double>();
    EXPECT_NEAR(r["timed_s"].get<double>(), T, 1e-12 * T);
  }
}

// Under the flow fidelity the draws are simulations of their own, and the report says so.
TEST(Bands, FlowFidelityDrawsAreSimulated) {
  RunConfig c = paper_run("ipsc2", 4, "pair-rs", "scenes/kurc/1pot.json", 96);
  c.fidelity = Fidelity::Flow;
  const auto r = run_banded(c, {.draws = 8, .seed = 1});
  ASSERT_EQ(r["bands"]["method"], "simulated") << r["bands"].dump();
  EXPECT_TRUE(r["bands"].contains("why_simulated"));
  EXPECT_LE(r["bands"]["virtual_time_s"]["p05"].get<double>(),
            r["bands"]["virtual_time_s"]["p95"].get<double>());
}
