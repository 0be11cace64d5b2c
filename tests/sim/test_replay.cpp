// sim: a run recorded on one machine and replayed on another gives, field by field, the report
// of a full run on the other (src/sim/replay.cpp); a replay the trace cannot reproduce is
// detected and the point runs in full.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "run/batch.hpp"
#include "sim/replay.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

const std::string kRoot = ZCUBE_SOURCE_DIR;

nlohmann::json record_point(const RunConfig& cfg, std::vector<std::uint8_t>* trace) {
  if (!trace) return report_json(run_simulation(cfg).report);
  std::shared_ptr<CallTrace> t;
  RunResult r = record_simulation(cfg, nullptr, t);
  if (t) *trace = t->serialize();
  return report_json(r.report);
}

std::optional<nlohmann::json> replay_point(const RunConfig& cfg,
                                           const std::vector<std::uint8_t>& trace) {
  auto t = std::make_shared<const CallTrace>(CallTrace::parse(trace));
  auto r = replay_simulation(cfg, nullptr, t);
  if (!r) return std::nullopt;
  return report_json(r->report);
}

// Every deterministic field: all but the host's wall time and memory.
nlohmann::json deterministic(nlohmann::json r) {
  r.erase("host");
  return r;
}

// Records `a`, replays it for each of `others` (all one key), and checks each replay against
// the other's full run. Returns how the points ran.
ReplayCounts expect_replays_exact(const RunConfig& a, const std::vector<RunConfig>& others) {
  std::vector<RunConfig> points = {a};
  points.insert(points.end(), others.begin(), others.end());
  TraceStore traces;
  ReplayCounts counts;
  const ReplayRunner runner{[](const RunConfig&) { return std::string("key"); }, record_point,
                            replay_point};
  const auto replayed = run_batch_replaying(points, 2, runner, traces, {}, &counts);
  const auto full = run_batch(
      others, 2, [](const RunConfig& c) { return report_json(run_simulation(c).report); });
  EXPECT_EQ(counts.recorded, 1u);
  EXPECT_EQ(replayed.front()["status"], "ok") << replayed.front().dump();
  for (std::size_t i = 0; i < others.size(); ++i) {
    const auto got = deterministic(replayed[i + 1]), want = deterministic(full[i]);
    EXPECT_EQ(got, want) << "point " << i + 1 << ": "
                         << nlohmann::json::diff(want, got).dump().substr(0, 2000);
  }
  return counts;
}

RunConfig point(const std::string& algorithm, const std::string& scene, int nodes, int size) {
  RunConfig c = sim_config("ipsc2", nodes, Topology::Cube, Fidelity::Circuit);
  c.algorithm = algorithm;
  c.scene_path = kRoot + "/scenes/" + scene;
  c.width = c.height = size;
  c.compare_with_sequential = true;
  return c;
}

// Other CPU costs and network (the iPSC/860), other latency, bandwidth and CPU speed under the
// flow and analytic models.
std::vector<RunConfig> other_machines(const RunConfig& a) {
  RunConfig b = a, c = a, d = a;
  b.machine = "ipsc860";
  c.what_ifs.set("latency", {27.5e-6});
  c.what_ifs.set("bandwidth", {11e6});
  c.what_ifs.set("cpu-scale", {0.3});
  c.fidelity = Fidelity::Flow;
  d.what_ifs.set("per-hop", {40e-6});
  d.what_ifs.set("cpu-scale", {2.5});
  d.fidelity = Fidelity::Analytic;
  return {b, c, d};
}

void expect_all_replayed(const RunConfig& a) {
  const ReplayCounts n = expect_replays_exact(a, other_machines(a));
  EXPECT_EQ(n.replayed, 3u);
  EXPECT_EQ(n.diverged, 0u);
}

} // namespace

TEST(Replay, ElasticWithRequestedVerticesAndFrames) {
  RunConfig a = point("elastic", "teapot.json", 8, 96);
  a.options.values = {{"vertices", "request"}};
  a.options.frames = 2;
  expect_all_replayed(a);
}

TEST(Replay, KurcSchemes) {
  for (const char* algo : {"pair-rs", "zbuf-exc", "aapc-hbp"})
    expect_all_replayed(point(algo, "kurc/2pot.json", 8, 128));
}

TEST(Replay, BlazekMethods) {
  for (const char* algo :
       {"host-initiated", "node-initiated", "object-forwarding", "host-broadcast"}) {
    SCOPED_TRACE(algo);
    const RunConfig a = point(algo, "blazek/spheres_16.json", 8, 96);
    const ReplayCounts n = expect_replays_exact(a, other_machines(a));
    EXPECT_EQ(n.replayed + n.diverged, 3u);
  }
}

TEST(Replay, CompositingStudy) {
  expect_all_replayed(point("compositing-study", "kurc/2pot.json", 8, 96));
}

// A node memory the run outgrows: the replay fails at the same call with the same message.
TEST(Replay, OutOfNodeMemoryAtTheSameCall) {
  const RunConfig a = point("zbuf-exc", "kurc/2pot.json", 8, 256);
  RunConfig b = a;
  b.what_ifs.set("memory", {1.2e6});
  const auto full = run_simulation_isolated(b);
  ASSERT_EQ(full["status"], "out_of_memory") << full.dump();
  EXPECT_EQ(full["error"].get<std::string>().find("operating system"), std::string::npos)
      << full["error"]; // it fails in the algorithm, not before
  const ReplayCounts n = expect_replays_exact(a, {b});
  EXPECT_EQ(n.replayed, 1u);
}

// Node 0 takes two messages from any source: node 1's is sent after a long computation, node 2's
// is long. On the iPSC/2 node 2's arrives first; a CPU 100000 times faster makes node 1's first,
// which the recorded calls cannot reproduce: the replay is abandoned and the point runs in full.
TEST(Replay, DivergenceFallsBackToAFullRun) {
  auto algo = std::make_shared<Algorithm>();
  algo->name = "any-source";
  algo->node = [](NodeContext& ctx) {
    Comm& c = ctx.comm();
    if (c.rank() == 0) {
      auto phase = ctx.phase("gather");
      for (int i = 0; i < 2; ++i)
        c.recv(kAnySource, 7);
    } else if (c.rank() == 1) {
      Counters w;
      w.pixels_written = 1'000'000;
      ctx.charge(w);
      c.send(0, 7, Bytes(4));
    } else if (c.rank() == 2) {
      c.send(0, 7, Bytes(100'000));
    }
  };
  RunConfig a = sim_config("ipsc2", 4, Topology::Cube, Fidelity::Circuit);
  a.custom = algo;
  RunConfig b = a;
  b.what_ifs.set("cpu-scale", {1e-5});
  const ReplayCounts n = expect_replays_exact(a, {b});
  EXPECT_EQ(n.diverged, 1u);
  EXPECT_EQ(n.replayed, 0u);
  EXPECT_EQ(n.full, 1u);
}
