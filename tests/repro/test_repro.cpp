// The reproduction machinery: NNLS, cost groups and the calibrated tables, paper-figure matching,
// sweeps (expansion, invalid points, failures that do not sink the others), regression diffs, and
// that the committed results/ are current for a subset of points.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "csv.hpp"

#include "machine/cpu_model.hpp"
#include "machine/machine.hpp"
#include "repro/paper_figures.hpp"
#include "repro/regress.hpp"
#include "repro/reproduce.hpp"
#include "repro/simulate.hpp"
#include "repro/sweep.hpp"
#include "util/error.hpp"
#include "util/nnls.hpp"

using namespace zc;

namespace {

const std::string kRoot = ZCUBE_SOURCE_DIR;

using test::read_csv;

} // namespace

TEST(Nnls, EqualsLeastSquaresWhenThatIsNonNegative) {
  // Exact system: x = (1, 2).
  const Matrix A = {{1, 0}, {0, 1}, {1, 1}};
  const auto x = nnls(A, {1, 2, 3});
  EXPECT_NEAR(x[0], 1, 1e-12);
  EXPECT_NEAR(x[1], 2, 1e-12);
}

TEST(Nnls, ClampsANegativeComponentAndMeetsTheKuhnTuckerConditions) {
  // Unconstrained least squares gives x1 < 0; NNLS must give x1 = 0, x0 = argmin over x0 alone.
  const Matrix A = {{1, 1}, {1, 2}, {1, 3}};
  const std::vector<double> b = {3, 2, 1};
  const auto x = nnls(A, b);
  EXPECT_EQ(x[1], 0);
  EXPECT_NEAR(x[0], 2, 1e-12); // mean of b
  // Gradient A^T (b - A x) <= 0 on the clamped component.
  double g1 = 0;
  for (int r = 0; r < 3; ++r)
    g1 += A[r][1] * (b[r] - A[r][0] * x[0]);
  EXPECT_LE(g1, 1e-12);
  EXPECT_THROW(nnls({{1, 2}, {3}}, {1, 2}), std::invalid_argument);
}

TEST(CostGroups, EveryCounterFieldIsInExactlyOneGroup) {
  CostTable t;
  std::multiset<std::string> seen;
  for (const auto& g : cost_groups())
    for (const auto& f : g.fields)
      seen.insert("cost_" + f);
  for (auto& [id, v] : t.fields())
    EXPECT_EQ(seen.count(id), 1u) << id;
  EXPECT_EQ(seen.size(), t.fields().size());
}

TEST(CostGroups, ScalingMultipliesOnlyTheGroupsFields) {
  const CostTable p = prior_i386_costs();
  std::vector<double> k(cost_groups().size(), 1.0);
  k[4] = 3.0; // merge
  CostTable s = scale_groups(p, k);
  EXPECT_DOUBLE_EQ(s.merge_ops, 3 * p.merge_ops);
  EXPECT_DOUBLE_EQ(s.spans, p.spans);
  EXPECT_EQ(cost_groups()[4].name, "merge");
}

TEST(CalibratedTables, EachMachineUsesItsOwnCpusPhysicalTableWithinThePlausibleRange) {
  const auto k = calibrated_group_scale();
  ASSERT_EQ(k.size(), cost_groups().size());
  for (double v : k) {
    EXPECT_GE(v, plausible_low());
    EXPECT_LE(v, plausible_high());
  }
  EXPECT_EQ(machine_spec("ipsc2").cpu, "i80386");
  EXPECT_EQ(machine_spec("ipsc860").cpu, "i860xr");
  EXPECT_EQ(machine_spec("volvox").cpu, "i860xr");
  const CostTable expect386 = cpu_seconds(cpu_model("i80386"), k);
  const CostTable expect860 = cpu_seconds(cpu_model("i860xr"), k);
  EXPECT_EQ(machine_spec("ipsc2").cost.pixels_written, expect386.pixels_written);
  EXPECT_EQ(machine_spec("ipsc860").cost.vertices_transformed, expect860.vertices_transformed);
  // The i860 is faster at every operation that costs anything, but not by one ratio.
  CostTable a = expect386, b = expect860;
  const auto fa = a.fields(), fb = b.fields();
  double lo = 1e300, hi = 0;
  for (std::size_t i = 0; i < fa.size(); ++i) {
    if (*fa[i].second == 0) continue;
    const double r = *fa[i].second / *fb[i].second;
    EXPECT_GT(r, 1) << fa[i].first;
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  EXPECT_GT(hi / lo, 1.5);
}

TEST(CpuModel, AVertexTransformCostsItsInstructionMixAtTheDocumentedClocks) {
  // Hand sum of machines/cpu/operations.json's vertex mix at the 80387's clocks.
  const CpuModel& c = cpu_model("i80386");
  const double expect = 16 * 20 + 38 * 33 + 27 * 28 + 16 * 44 + 2 * 89 + 125 + 7 * 40 + 15 * 2 +
                        6 * 4 + 4 * 2 + 8 * 8 + 40;
  EXPECT_DOUBLE_EQ(c.cycles.vertices_transformed, expect);
  EXPECT_DOUBLE_EQ(c.clock_hz, 16e6);
  EXPECT_DOUBLE_EQ(cpu_seconds(c).vertices_transformed, expect / 16e6);
  EXPECT_EQ(c.cycles.pixels_final, 0);
  // A memory copy stays within the bus bounds of docs/machines.md: 5-16 MB/s on the 16 MHz 386,
  // tens of MB/s on the i860.
  EXPECT_GT(1 / cpu_seconds(c).bytes_packed, 5e6);
  EXPECT_LT(1 / cpu_seconds(c).bytes_packed, 16e6);
  EXPECT_GT(1 / cpu_seconds(cpu_model("i860xr")).bytes_packed, 20e6);
  EXPECT_THROW(cpu_model("z80"), UsageError);
}

TEST(BoundedLsq, StaysInsideItsBoxAndFindsTheInteriorOptimum) {
  const Matrix A = {{1, 0}, {0, 1}, {1, 1}};
  // Unconstrained optimum (1, 2) lies inside [0, 3]^2.
  auto x = bounded_lsq(A, {1, 2, 3}, {0, 0}, {3, 3});
  EXPECT_NEAR(x[0], 1, 1e-12);
  EXPECT_NEAR(x[1], 2, 1e-12);
  // With x1 <= 1.5 the optimum moves to the bound and x0 compensates: minimise
  // (x0-1)^2 + (1.5-2)^2 + (x0+1.5-3)^2 -> x0 = 1.25.
  x = bounded_lsq(A, {1, 2, 3}, {0, 0}, {3, 1.5});
  EXPECT_NEAR(x[0], 1.25, 1e-12);
  EXPECT_DOUBLE_EQ(x[1], 1.5);
  EXPECT_THROW(bounded_lsq(A, {1, 2, 3}, {1, 0}, {0, 1}), std::invalid_argument);
}

TEST(BoundedLsq, MeetsTheKuhnTuckerConditionsOnRandomIllScaledProblems) {
  // At the optimum of a box-constrained least squares, the gradient A^T (b - A x) is 0 on a free
  // variable, <= 0 at a lower bound and >= 0 at an upper one; columns scaled 1e-3..1e3 apart would
  // lose those digits to the normal equations' squared condition number.
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0, 1);
  for (int t = 0; t < 300; ++t) {
    const int n = 1 + t % 6, m = n + 4 + t % 5;
    Matrix A(m, std::vector<double>(n));
    std::vector<double> b(m), lo(n, 0.5), hi(n, 2.0);
    for (auto& row : A)
      for (int j = 0; j < n; ++j)
        row[j] = std::fabs(normal(rng)) * std::pow(10.0, 3 * (j % 3) - 3);
    for (auto& v : b)
      v = 3 * normal(rng);
    const auto x = bounded_lsq(A, b, lo, hi);
    for (int j = 0; j < n; ++j) {
      double w = 0, scale = 0;
      for (int r = 0; r < m; ++r) {
        double e = b[r];
        for (int k = 0; k < n; ++k)
          e -= A[r][k] * x[k];
        w += A[r][j] * e;
        scale += std::fabs(A[r][j]) * (std::fabs(b[r]) + 1);
      }
      const double tol = 1e-9 * scale;
      ASSERT_GE(x[j], lo[j]);
      ASSERT_LE(x[j], hi[j]);
      if (x[j] == lo[j])
        EXPECT_LE(w, tol) << t << " " << j;
      else if (x[j] == hi[j])
        EXPECT_GE(w, -tol) << t << " " << j;
      else
        EXPECT_NEAR(w, 0, tol) << t << " " << j;
    }
  }
}

TEST(PaperFigures, AKurcRunGetsItsThreeTable2FiguresWithTheirErrors) {
  nlohmann::json r = {
      {"status", "ok"},
      {"algorithm", "pair-rs"},
      {"machine", "ipsc2"},
      {"topology", "cube"},
      {"nodes", 16},
      {"virtual_time_s", 2.0},
      {"scene", {{"path", "/x/scenes/kurc/1pot.json"}, {"width", 400}, {"height", 400}}},
      {"phases",
       {{{"name", "span_list_creation"}, {"max_s", 0.322}},
        {{"name", "local_zbuffer"}, {"max_s", 0.868}},
        {{"name", "pixel_merging"}, {"max_s", 0.174}}}}};
  const auto f = paper_figures_for(r);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_NEAR(f[0]["rel_error"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(f[1]["rel_error"].get<double>(), 1.0, 1e-12);  // 868 against 434
  EXPECT_NEAR(f[2]["rel_error"].get<double>(), -0.5, 1e-12); // 174 against 348
  r["nodes"] = 8;                                            // held out: no figure
  EXPECT_TRUE(paper_figures_for(r).empty());
  r["nodes"] = 16;
  r["scene"]["width"] = 640;
  EXPECT_TRUE(paper_figures_for(r).empty());
}

TEST(PaperFigures, CharlesSpeedupNeedsTheSequentialTime) {
  nlohmann::json r = {{"status", "ok"},
                      {"algorithm", "elastic"},
                      {"machine", "ipsc860"},
                      {"topology", "cube"},
                      {"nodes", 16},
                      {"virtual_time_s", 1.0},
                      {"phases", nlohmann::json::array()},
                      {"scene", {{"path", kCharlesTeapotScene}, {"width", 512}, {"height", 512}}}};
  EXPECT_TRUE(needs_sequential_time(r));
  // The default teapot is not the paper's (Table 1 frames Charles's): no figure.
  r["scene"]["path"] = "scenes/teapot.json";
  EXPECT_FALSE(needs_sequential_time(r));
  r["scene"]["path"] = kCharlesTeapotScene;
  auto f = paper_figures_for(r);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_FALSE(f[0].contains("predicted"));
  f = paper_figures_for(r, 8.3 * 1.1);
  EXPECT_NEAR(f[0]["rel_error"].get<double>(), 0.1, 1e-12);
  r["topology"] = "ring";
  EXPECT_FALSE(needs_sequential_time(r));
}

// A what-if run still gets the paper's figure to compare with, marked as not the paper's machine.
TEST(PaperFigures, AWhatIfRunsFiguresAreMarked) {
  nlohmann::json r = {
      {"status", "ok"},
      {"machine", "ipsc860"},
      {"topology", "cube"},
      {"nodes", 16},
      {"algorithm", "elastic"},
      {"virtual_time_s", 1.0},
      {"phases", nlohmann::json::array()},
      {"what_if", nlohmann::json::object()},
      {"scene", {{"path", kRoot + "/" + kCharlesTeapotScene}, {"width", 512}, {"height", 512}}}};
  auto f = paper_figures_for(r, 8.3);
  ASSERT_EQ(f.size(), 1u) << r.dump();
  EXPECT_FALSE(f[0].contains("what_if"));
  r["what_if"]["cpu_scale"] = 2.0;
  f = paper_figures_for(r, 8.3);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0]["what_if"], true);
}

// A platform file states its own node count: its baseline runs on it without --nodes 1 (which the
// file would refuse), sequential rendering on node 0 alone.
TEST(Sweep, ABaselineOnAPlatformFileTakesTheFilesNodes) {
  const std::string xml = kRoot + "/platforms/volvox-ring-8.xml";
  const std::vector<SweepAxis> axes = {{"machine", {xml}}, {"algorithm", {"elastic"}}};
  auto pts = expand_sweep(axes, kRoot + "/scenes/teapot.json");
  add_baselines(axes, pts, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 2u);
  ASSERT_TRUE(is_baseline(pts[1]));
  ASSERT_TRUE(pts[1].config.has_value()) << pts[1].error;
  EXPECT_EQ(pts[1].config->nodes, 0); // the file's
  EXPECT_EQ(pts[1].config->algorithm, "sequential");
  const std::vector<nlohmann::json> reps = {
      {{"status", "ok"}, {"nodes", 8}, {"virtual_time_s", 2.0}},
      {{"status", "ok"}, {"nodes", 8}, {"virtual_time_s", 8.0}}};
  auto rows = sweep_rows(axes, pts, reps);
  ASSERT_TRUE(add_speedups(pts, reps, rows));
  EXPECT_DOUBLE_EQ(rows[0]["efficiency"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(rows[1]["efficiency"].get<double>(), 1.0); // one node works
}

TEST(Sweep, ExpandsTheCartesianProductFirstAxisSlowest) {
  const auto pts = expand_sweep({{"nodes", {"1", "2", "3"}}, {"latency", {"10us", "1ms"}}},
                                kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 6u);
  EXPECT_EQ(pts[0].values.at("nodes"), "1");
  EXPECT_EQ(pts[1].values.at("latency"), "1ms");
  EXPECT_EQ(pts[2].values.at("nodes"), "2");
  // 3 nodes is no hypercube: those points carry the reason, the others a configuration.
  for (const auto& p : pts) {
    EXPECT_EQ(p.config.has_value(), p.values.at("nodes") != "3");
    if (!p.config) {
      EXPECT_NE(p.error.find("power of two"), std::string::npos);
    }
  }
  EXPECT_DOUBLE_EQ(*pts[1].config->overrides.latency_s, 1e-3);
  EXPECT_THROW(split_list("1,,2", "nodes"), UsageError);
  EXPECT_THROW(split_list("", "nodes"), UsageError);
  const auto bad = expand_sweep({{"algorithm", {"elastic"}}, {"packet", {"10"}}}, "x.json");
  EXPECT_FALSE(bad[0].config.has_value()); // --packet does not apply to elastic
}

TEST(Batch, AFailingPointDoesNotLoseTheOthers) {
  SimConfig good;
  good.machine = "ipsc2";
  good.nodes = 2;
  good.algorithm = "elastic";
  good.scene_path = kRoot + "/scenes/teapot.json";
  good.width = good.height = 64;
  SimConfig missing = good;
  missing.scene_path = kRoot + "/no/such/scene.json";
  int calls = 0;
  const auto r =
      simulate_batch({missing, good, missing}, 2, [&](const BatchProgress&) { ++calls; });
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0]["status"], "error");
  EXPECT_NE(r[0]["error"].get<std::string>().find("scene.json"), std::string::npos);
  EXPECT_EQ(r[1]["status"], "ok");
  EXPECT_EQ(r[1]["image"]["identical_to_sequential"], true);
  EXPECT_EQ(r[2]["status"], "error");
  EXPECT_EQ(calls, 3);
}

TEST(Regress, ReportsEveryChangedQuantityAndMissingRuns) {
  std::map<std::string, nlohmann::json> a = {
      {"x", {{"virtual_time_s", 2.0}, {"image", {{"sha256", "ab"}}}}},
      {"y", {{"virtual_time_s", 1.0}}}};
  EXPECT_TRUE(compare_reduced(a, a).empty());
  auto b = a;
  b["x"]["virtual_time_s"] = 2.0000000000000004; // one ulp is a change
  b["x"]["image"]["sha256"] = "cd";
  b.erase("y");
  b["z"] = nlohmann::json::object();
  const auto d = compare_reduced(a, b);
  ASSERT_EQ(d.size(), 4u);
  std::set<std::string> what;
  for (const auto& e : d)
    what.insert(e.run + ":" + e.quantity);
  EXPECT_TRUE(what.count("x:virtual_time_s"));
  EXPECT_TRUE(what.count("x:image.sha256"));
  EXPECT_TRUE(what.count("y:(run)"));
  EXPECT_TRUE(what.count("z:(run)"));
}

// A tolerance for rounding noise (4.2e-16 was once reported as a "difference"); a run whose status
// changed is one row, and a side that lacks a sub-report gives one row per value, never a blob.
TEST(Regress, RelativeToleranceAndOneRowPerValue) {
  std::map<std::string, nlohmann::json> a = {
      {"x", {{"status", "ok"}, {"virtual_time_s", 2.0}, {"phases", {{"merge", 1.0}}}}},
      {"y", {{"status", "ok"}, {"virtual_time_s", 1.0}}}};
  auto b = a;
  b["x"]["virtual_time_s"] = 2.0 * (1 + 4.2e-16);
  EXPECT_EQ(compare_reduced(a, b, 0).size(), 1u);
  EXPECT_TRUE(compare_reduced(a, b, 1e-9).empty());
  b["x"]["virtual_time_s"] = 2.0 * (1 + 1e-6);
  EXPECT_EQ(compare_reduced(a, b, 1e-9).size(), 1u);
  b = a;
  b["y"] = {{"status", "error"}, {"error", "node 3 lost"}};
  auto d = compare_reduced(a, b, 1e-9);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].quantity, "status");
  EXPECT_EQ(d[0].after, "error (node 3 lost)");
  b = a;
  b["x"].erase("phases");
  d = compare_reduced(a, b, 1e-9);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].quantity, "phases.merge");
  EXPECT_EQ(d[0].before, "1.0");
  EXPECT_EQ(d[0].after, "(none)");
  EXPECT_EQ(failed_runs({{"y", {{"status", "error"}, {"error", "why"}}}}).size(), 1u);
}

// --set with a key that is no run flag, or a value no run accepts, fails before anything runs.
TEST(Regress, BadOverridesAreUsageErrors) {
  const std::vector<RegressRun> runs = {{"seq", {{"algorithm", "sequential"}}}};
  EXPECT_THROW(run_regress(runs, kRoot, 1, {{"bogus", "1"}}), UsageError);
  try {
    run_regress(runs, kRoot, 1, {{"latency", "5parsecs"}});
    ADD_FAILURE() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("5parsecs"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

// The default `zcube reproduce` keeps the committed --full Blazek tables and writes beside them.
TEST(Reproduce, NeverDegradesTheFullBlazekTables) {
  const auto dir = std::filesystem::temp_directory_path() / "zcube-test-keep";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "blazek");
  // What `zcube reproduce blazek --full` writes: rows up to 2048 spheres.
  std::ofstream(dir / "blazek/speedup.csv")
      << "method,spheres,nodes,virtual_s,speedup,efficiency\n"
         "node-initiated,64,32,1.5,20,0.6\nnode-initiated,2048,32,30,28,0.9\n";
  ReproduceOptions o;
  o.root = kRoot;
  o.out = dir.string();
  std::string note;
  EXPECT_EQ(plan_directory(o, blazek_plan(o), &note), o.out + "/blazek-quick");
  EXPECT_NE(note.find("--full"), std::string::npos) << note;
  o.full = true;
  EXPECT_EQ(plan_directory(o, blazek_plan(o), &note), o.out + "/blazek");
  o.full = false;
  o.overwrite = true;
  EXPECT_EQ(plan_directory(o, blazek_plan(o), &note), o.out + "/blazek");
  o.overwrite = false;
  EXPECT_EQ(plan_directory(o, kurc_plan(o), &note), o.out + "/kurc");
  // Tables of the default grid are simply rewritten.
  std::ofstream(dir / "blazek/speedup.csv")
      << "method,spheres,nodes,virtual_s,speedup,efficiency\nnode-initiated,64,32,1.5,20,0.6\n";
  EXPECT_EQ(plan_directory(o, blazek_plan(o), &note), o.out + "/blazek");
  std::filesystem::remove_all(dir);
}

// Sweeps: the reference's run on one node (scanline for Kurc et al.) is the baseline of the points
// that share every other flag; --baseline adds it where missing.
TEST(Sweep, SpeedupsAgainstTheMatchingReferenceRun) {
  const std::vector<SweepAxis> axes = {
      {"algorithm", {"scanline", "pair-rs"}}, {"nodes", {"1", "4"}}, {"latency", {"10us", "1ms"}}};
  auto pts = expand_sweep(axes, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 8u);
  std::vector<nlohmann::json> reps;
  for (const auto& p : pts)
    reps.push_back({{"status", "ok"},
                    {"nodes", std::stoi(p.values.at("nodes"))},
                    {"virtual_time_s", p.values.at("algorithm") == "scanline" ? 8.0 : 2.0}});
  reps[0]["virtual_time_s"] = 8.0; // scanline, 1 node, 10us
  reps[1]["virtual_time_s"] = 4.0; // scanline, 1 node, 1ms
  auto rows = sweep_rows(axes, pts, reps);
  ASSERT_TRUE(add_speedups(pts, reps, rows));
  // pair-rs, 4 nodes, 1ms (index 7): 4 / 2.
  EXPECT_DOUBLE_EQ(rows[7]["speedup"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(rows[7]["efficiency"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(rows[6]["speedup"].get<double>(), 4.0);

  const std::vector<SweepAxis> no_seq = {{"algorithm", {"pair-rs"}}, {"nodes", {"2", "4"}}};
  auto p2 = expand_sweep(no_seq, kRoot + "/scenes/teapot.json");
  std::vector<nlohmann::json> r2(p2.size(), {{"status", "ok"}, {"virtual_time_s", 1.0}});
  auto rows2 = sweep_rows(no_seq, p2, r2);
  EXPECT_FALSE(add_speedups(p2, r2, rows2));
  add_baselines(no_seq, p2, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(p2.size(), 3u);
  EXPECT_TRUE(is_baseline(p2[2]));
  EXPECT_TRUE(p2[2].config.has_value()) << p2[2].error;
}

// A speed-up divides the timed region (elastic's per-picture loop, docs/papers.md), as zcube run's
// paper line does; a --timed axis is an option of the algorithm, so the baseline does not get it.
TEST(Sweep, SpeedupsDivideTheTimedRegionAndTimedIsAnAlgorithmOption) {
  const std::vector<SweepAxis> axes = {
      {"algorithm", {"elastic"}}, {"nodes", {"4"}}, {"timed", {"picture", "all"}}};
  auto pts = expand_sweep(axes, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 2u);
  add_baselines(axes, pts, kRoot + "/scenes/teapot.json");
  ASSERT_EQ(pts.size(), 3u); // one baseline serves both --timed values
  ASSERT_TRUE(is_baseline(pts[2]));
  ASSERT_TRUE(pts[2].config.has_value()) << pts[2].error;
  EXPECT_EQ(pts[2].values.at("timed"), "");
  const std::vector<nlohmann::json> reps = {
      {{"status", "ok"}, {"nodes", 4}, {"virtual_time_s", 3.0}, {"timed_s", 2.0}},
      {{"status", "ok"}, {"nodes", 4}, {"virtual_time_s", 3.0}, {"timed_s", 2.5}},
      {{"status", "ok"}, {"nodes", 1}, {"virtual_time_s", 8.0}}};
  auto rows = sweep_rows(axes, pts, reps);
  ASSERT_TRUE(add_speedups(pts, reps, rows));
  EXPECT_DOUBLE_EQ(rows[0]["virtual_s"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(rows[0]["timed_s"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(rows[0]["speedup"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(rows[1]["speedup"].get<double>(), 3.2);
  EXPECT_DOUBLE_EQ(rows[2]["timed_s"].get<double>(), 8.0); // no timed region: the whole run
}

// The committed results/ are a real run of `zcube reproduce`: a few points re-simulated now give
// the committed numbers (to their printed precision).
TEST(Reproduce, CommittedResultsAreCurrentForASubset) {
  ReproduceOptions o;
  o.root = kRoot;
  const auto kurc = kurc_plan(o), charles = charles_plan(o), blazek = blazek_plan(o);
  auto pick = [](const PaperPlan& p, const std::string& key) {
    for (const auto& pt : p.points)
      if (pt.key == key) return pt.cfg;
    ADD_FAILURE() << "no point " << key;
    return SimConfig{};
  };
  const std::vector<SimConfig> cfgs = {
      pick(kurc, "t2/16/1pot/pair-rs"), pick(charles, "el/teapot/256/cube/4"),
      pick(charles, "seq/teapot/256"), pick(blazek, "node-initiated/4/4")};
  const auto r = simulate_batch(cfgs, 2);
  for (const auto& rep : r)
    ASSERT_EQ(rep["status"], "ok") << rep.dump();
  // Equal to the committed figure within its printed precision.
  auto near = [](const std::string& committed, double now, double rel, double abs,
                 const std::string& what) {
    EXPECT_LE(std::fabs(std::stod(committed) - now), std::max(abs, rel * std::fabs(now)))
        << what << ": committed " << committed << ", now " << now;
  };
  int found = 0;
  for (const auto& row : read_csv(kRoot + "/results/kurc/table2.csv"))
    if (row.at("nodes") == "16" && row.at("scene") == "1pot" && row.at("scheme") == "pair-rs")
      for (const auto& p : r[0]["phases"])
        if (p["name"] == row.at("phase")) {
          near(row.at("predicted_ms"), p["max_s"].get<double>() * 1e3, 0, 0.0501,
               "kurc " + row.at("phase"));
          ++found;
        }
  for (const auto& row : read_csv(kRoot + "/results/charles/speedup.csv"))
    if (row.at("scene") == "teapot" && row.at("size") == "256" && row.at("topology") == "cube" &&
        row.at("nodes") == "4") {
      // reproduce divides the paper's timed region (virtual_s: timed_s when the run has one).
      near(row.at("virtual_s"), virtual_s(r[1]), 6e-6, 0, "charles virtual_s");
      near(row.at("speedup"), virtual_s(r[2]) / virtual_s(r[1]), 6e-4, 0, "charles speedup");
      ++found;
    }
  // One meaning per column name: kurc's speed-ups are over the three phases of Table 2
  // (render_s), which is not the whole run (virtual_s everywhere else).
  for (const auto& row : read_csv(kRoot + "/results/kurc/speedup.csv"))
    if (row.at("scheme") == "pair-rs" && row.at("scene") == "1pot" && row.at("size") == "400" &&
        row.at("nodes") == "16") {
      EXPECT_FALSE(row.count("virtual_s"));
      double three = 0;
      for (const auto& p : r[0]["phases"])
        for (const auto& k : kurc_phases())
          if (p["name"] == k) three += p["max_s"].get<double>();
      near(row.at("render_s"), three, 6e-6, 0, "kurc render_s");
      EXPECT_LT(three, r[0]["virtual_time_s"].get<double>() * 0.999);
      ++found;
    }
  for (const auto& row : read_csv(kRoot + "/results/blazek/speedup.csv"))
    if (row.at("method") == "node-initiated" && row.at("spheres") == "4" &&
        row.at("nodes") == "4") {
      near(row.at("virtual_s"), virtual_s(r[3]), 6e-6, 0, "blazek virtual_s");
      ++found;
    }
  EXPECT_EQ(found, 6);
}
