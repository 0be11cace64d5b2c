// The trace files of `zcube run --trace`: the Chrome/Perfetto JSON has one track per node, one
// flow per message, properly nested slices, and slices that add up to the report's busy,
// communication and idle times; the Paje file passes pj_dump. For every algorithm and fidelity.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "repro/simulate.hpp"
#include "sim/simulation.hpp"
#include "trace/chrome_trace.hpp"
#include "trace/paje_trace.hpp"

using namespace zc;

namespace {

struct Case {
  std::string algorithm, scene;
  int nodes;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> c = {{"sequential", "scenes/teapot.json", 1},
                                      {"elastic", "scenes/teapot.json", 8},
                                      {"aapc-hbp", "scenes/kurc/2pot.json", 8},
                                      {"pair-rs", "scenes/kurc/2pot.json", 8},
                                      {"zbuf-exc", "scenes/kurc/2pot.json", 8},
                                      {"host-initiated", "scenes/blazek/spheres_16.json", 4},
                                      {"node-initiated", "scenes/blazek/spheres_16.json", 4},
                                      {"host-broadcast", "scenes/blazek/spheres_16.json", 4},
                                      {"object-forwarding", "scenes/blazek/spheres_16.json", 4}};
  return c;
}

RunConfig config(const Case& k, Fidelity f) {
  RunConfig c;
  c.algorithm = k.algorithm;
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/" + k.scene;
  c.nodes = k.nodes;
  c.fidelity = f;
  c.width = c.height = 96;
  c.compare_with_sequential = false;
  c.timeline = true;
  return c;
}

// Every case at every fidelity, simulated once for all the tests below.
const std::vector<nlohmann::json>& reports() {
  static const std::vector<nlohmann::json> r = [] {
    std::vector<RunConfig> pts;
    for (const auto& k : cases())
      for (Fidelity f : {Fidelity::Analytic, Fidelity::Flow, Fidelity::Circuit})
        pts.push_back(config(k, f));
    return simulate_batch(pts, 2);
  }();
  return r;
}

std::string name(const nlohmann::json& r) {
  return r.value("algorithm", "?") + "/" + r.value("fidelity", "?");
}

} // namespace

TEST(ChromeTrace, OneTrackPerNodeOneFlowPerMessageSlicesSumToTheReport) {
  for (const auto& r : reports()) {
    ASSERT_EQ(r["status"], "ok") << name(r) << ": " << r.dump().substr(0, 400);
    const Timeline tl = read_timeline(r, "report");
    const auto j = nlohmann::json::parse(chrome_trace(tl, r["topology"]).dump());
    std::map<int, std::map<std::string, double>> sums; // tid -> activity -> seconds
    std::map<int, int> slices;                         // tid -> activity slices
    int tracks = 0, flows_out = 0, flows_in = 0;
    for (const auto& e : j["traceEvents"]) {
      if (e["ph"] == "M" && e["name"] == "thread_name") ++tracks;
      if (e["ph"] == "s") ++flows_out;
      if (e["ph"] == "f") ++flows_in;
      if (e["ph"] == "X" && e["cat"] == "activity") {
        sums[e["tid"].get<int>()][e["name"]] += e["dur"].get<double>() * 1e-6;
        ++slices[e["tid"].get<int>()];
      }
    }
    const auto& per_node = r["per_node"];
    EXPECT_EQ(tracks, int(per_node.size())) << name(r); // the P nodes and the host, if it ran
    EXPECT_EQ(flows_out, r["communication"]["messages"].get<int>()) << name(r);
    EXPECT_EQ(flows_in, flows_out) << name(r);
    for (std::size_t i = 0; i < per_node.size(); ++i) {
      auto& s = sums[int(i)];
      const auto& pn = per_node[i];
      // Each slice's ends are rounded to the nanosecond.
      const double tol = 1e-9 * (1 + slices[int(i)]);
      EXPECT_NEAR(s["compute"], pn["busy_s"].get<double>(), tol) << name(r) << " node " << i;
      EXPECT_NEAR(s["send"] + s["wait"], pn["comm_s"].get<double>(), tol)
          << name(r) << " node " << i;
      EXPECT_NEAR(s["idle"], pn["idle_s"].get<double>(), tol) << name(r) << " node " << i;
    }
  }
}

// Perfetto reads ts and dur as microseconds rounded to nanoseconds and keeps, per track, only
// slices that nest: each slice lies inside the one it starts in, or after it.
TEST(ChromeTrace, SlicesNestProperlyOnEveryTrack) {
  for (const auto& r : reports()) {
    ASSERT_EQ(r["status"], "ok") << name(r);
    const auto j = chrome_trace(read_timeline(r, "report"), r["topology"]);
    std::map<int, std::vector<std::pair<std::int64_t, std::int64_t>>> tracks; // tid -> [begin, end)
    for (const auto& e : j["traceEvents"])
      if (e["ph"] == "X") {
        const std::int64_t b = std::llround(e["ts"].get<double>() * 1000.0);
        tracks[e["tid"].get<int>()].push_back(
            {b, b + std::llround(e["dur"].get<double>() * 1000.0)});
      }
    for (auto& [tid, slices] : tracks) {
      // Outer first: by start, the longer one first at a common start.
      std::sort(slices.begin(), slices.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : a.second > b.second;
      });
      std::vector<std::int64_t> open; // ends of the slices enclosing the current one
      int crossing = 0;
      for (const auto& [b, e] : slices) {
        while (!open.empty() && open.back() <= b)
          open.pop_back();
        if (!open.empty() && e > open.back()) ++crossing;
        open.push_back(e);
      }
      EXPECT_EQ(crossing, 0) << name(r) << " track " << tid << ": slices crossing another";
    }
  }
}

TEST(ChromeTrace, HostLinkCountersNamedAsThePlatformsLinks) {
  for (const auto& r : reports()) {
    if (r["algorithm"] != "host-initiated") continue;
    const auto j = chrome_trace(read_timeline(r, "report"), r["topology"]);
    std::set<std::string> names;
    for (const auto& e : j["traceEvents"])
      if (e["ph"] == "C") names.insert(e["name"]);
    EXPECT_TRUE(names.count("host-down (srm->node 0)")) << name(r);
    EXPECT_TRUE(names.count("host-up (node 0->srm)")) << name(r);
    for (const auto& n : names)
      EXPECT_EQ(n.find("->" + std::to_string(r["nodes"].get<int>())), std::string::npos) << n;
  }
}

TEST(PajeTrace, PassesPjDumpWithEveryMessageAsALink) {
  if (std::system("command -v pj_dump >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "pj_dump not installed (scripts/setup.sh installs pajeng)";
  const auto dir = std::filesystem::temp_directory_path() / "zcube-test-paje";
  std::filesystem::create_directories(dir);
  for (const auto& r : reports()) {
    ASSERT_EQ(r["status"], "ok") << name(r);
    const auto trace = dir / "run.trace", dump = dir / "dump.txt", err = dir / "err.txt";
    {
      std::ofstream out(trace);
      write_paje_trace(read_timeline(r, "report"), r["topology"], out);
    }
    const std::string cmd =
        "pj_dump " + trace.string() + " >" + dump.string() + " 2>" + err.string();
    ASSERT_EQ(std::system(cmd.c_str()), 0)
        << name(r) << ": pj_dump failed: " << std::ifstream(err).rdbuf();
    std::ifstream in(dump);
    int links = 0, states = 0;
    for (std::string line; std::getline(in, line);) {
      links += line.rfind("Link,", 0) == 0;
      states += line.rfind("State,", 0) == 0;
    }
    EXPECT_EQ(links, r["communication"]["messages"].get<int>()) << name(r);
    EXPECT_GT(states, 0) << name(r);
  }
  std::filesystem::remove_all(dir);
}
