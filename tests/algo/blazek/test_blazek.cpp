// Blazek 1991's four decompositions on the simulated iPSC/2 (with its host computer, srm).
#include <gtest/gtest.h>

#include "algo/blazek/blazek_methods.hpp"
#include "machine/platform_xml.hpp"
#include "sim_fixtures.hpp"

using namespace zc;
using namespace zc::test;

namespace {

nlohmann::json run_method(const std::string& algo, const std::string& scene, int P, int size,
                          std::map<std::string, std::string> opt = {}, bool compare = true) {
  RunConfig c = sim_config("ipsc2", P, Topology::Cube, Fidelity::Circuit);
  c.algorithm = algo;
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/" + scene;
  c.width = c.height = size;
  c.options.values = std::move(opt);
  c.compare_with_sequential = compare;
  c.what_ifs.set("memory", {64.0 * 1048576});
  return run_simulation_isolated(c);
}

double busy_spread(const nlohmann::json& r) {
  double mx = 0, mn = 1e300;
  for (const auto& n : r["per_node"]) {
    if (n["rank"] == kHostComputerName) continue;
    mx = std::max(mx, n["busy_s"].get<double>());
    mn = std::min(mn, n["busy_s"].get<double>());
  }
  return mx - mn;
}

// Every method the registry declares for Blazek, with each value of its choice options and the
// extremes of its integer ones (--packet 10 and 1000).
std::vector<std::pair<std::string, std::map<std::string, std::string>>> methods() {
  std::vector<std::pair<std::string, std::map<std::string, std::string>>> v;
  for (const Algorithm& a : blazek_algorithms()) {
    if (a.options.empty()) v.push_back({a.name, {}});
    for (const OptionSpec& o : a.options) {
      if (o.kind == OptionSpec::Kind::Choice)
        for (const auto& c : o.choices)
          v.push_back({a.name, {{o.name, c}}});
      if (o.kind == OptionSpec::Kind::Integer)
        for (long long n : {o.min, o.max})
          v.push_back({a.name, {{o.name, std::to_string(n)}}});
    }
  }
  return v;
}

} // namespace

TEST(Blazek, EveryMethodOnEveryCubeGivesTheSequentialImage) {
  const auto methods = ::methods();
  ASSERT_EQ(methods.size(), 7u); // four methods, two with two choices, packet at both extremes
  for (const char* scene : {"scenes/blazek_fig9.sdl", "scenes/blazek/spheres_16.json"})
    for (const auto& [m, opt] : methods)
      for (int P : {1, 2, 4, 8, 16, 32}) {
        auto r = run_method(m, scene, P, 64, opt);
        ASSERT_EQ(r["status"], "ok") << r.dump();
        EXPECT_EQ(r["image"]["identical_to_sequential"], true) << m << " P=" << P << " " << scene;
      }
}

TEST(Blazek, PacketSizeChangesTheTimeNotTheImage) {
  auto a =
      run_method("host-initiated", "scenes/blazek/spheres_16.json", 8, 128, {{"packet", "10"}});
  auto b =
      run_method("host-initiated", "scenes/blazek/spheres_16.json", 8, 128, {{"packet", "1000"}});
  ASSERT_EQ(a["status"], "ok") << a.dump();
  ASSERT_EQ(b["status"], "ok") << b.dump();
  EXPECT_EQ(a["image"]["sha256"], b["image"]["sha256"]);
  EXPECT_NE(a["virtual_time_s"], b["virtual_time_s"]);
  EXPECT_GT(a["communication"]["messages"].get<int>(), b["communication"]["messages"].get<int>());
}

TEST(Blazek, ForwardingGrowsAsStripsNarrow) {
  std::int64_t last = -1;
  for (int P : {2, 4, 8, 16, 32}) {
    auto r = run_method("object-forwarding", "scenes/blazek/spheres_16.json", P, 128, {}, false);
    const auto f = r["blazek"]["forwarded_messages"].get<std::int64_t>();
    EXPECT_GT(f, last) << "P=" << P;
    last = f;
  }
}

TEST(Blazek, InterleavedLinesBalanceAClusteredSceneBetterThanStrips) {
  auto s =
      run_method("host-broadcast", "scenes/blazek/clustered.json", 8, 128, {{"lines", "strips"}});
  auto i = run_method("host-broadcast", "scenes/blazek/clustered.json", 8, 128,
                      {{"lines", "interleaved"}});
  ASSERT_EQ(s["status"], "ok") << s.dump();
  ASSERT_EQ(i["status"], "ok") << i.dump();
  EXPECT_EQ(s["image"]["sha256"], i["image"]["sha256"]);
  EXPECT_LT(busy_spread(i), busy_spread(s) / 2);
}

TEST(Blazek, A1024FrameBufferDoesNotFitAFourMegabyteNodeButStripsDo) {
  RunConfig c = sim_config("ipsc2", 16, Topology::Cube, Fidelity::Circuit);
  c.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/blazek/spheres_16.json";
  c.width = c.height = 1024;
  c.compare_with_sequential = false;
  c.algorithm = "node-initiated";
  EXPECT_EQ(run_simulation_isolated(c)["status"], "out_of_memory");
  c.algorithm = "object-forwarding";
  EXPECT_EQ(run_simulation_isolated(c)["status"], "ok");
}

TEST(Blazek, NodesTransformATessellationsVerticesOnceShippedPolygonsThreeTimes) {
  const char* scene = "scenes/blazek/spheres_16.json";
  const auto seq = run_method("sequential", scene, 1, 64, {}, false);
  const auto vt = [](const nlohmann::json& r) {
    return r["counters"]["vertices_transformed"].get<std::uint64_t>();
  };
  EXPECT_EQ(vt(run_method("node-initiated", scene, 4, 64)), vt(seq));
  EXPECT_EQ(vt(run_method("host-initiated", scene, 4, 64)),
            3 * seq["scene"]["triangles"].get<std::uint64_t>());
}
