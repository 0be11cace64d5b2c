// The papers' qualitative statements, checked on the calibrated machine models at small sizes
// where each statement holds (issue 12, item 7(d)). These are claims about the model, not about
// the fit: a check that fails after a re-calibration says the refit broke a published statement.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "sim/simulation.hpp"

using namespace zc;

namespace {

const std::string kRoot = ZCUBE_SOURCE_DIR;

nlohmann::json run(const std::string& machine, int nodes, const std::string& algorithm,
                   const std::string& scene, int size, Topology topo = Topology::Cube) {
  SimConfig c;
  c.machine = machine;
  c.nodes = nodes;
  c.topology = topo;
  c.algorithm = algorithm;
  c.scene_path = kRoot + "/" + scene;
  c.width = c.height = size;
  c.compare_with_sequential = false;
  return run_simulation_isolated(c);
}

double phase_s(const nlohmann::json& r, const std::string& name) {
  for (const auto& p : r["phases"])
    if (p["name"] == name) return p["max_s"].get<double>();
  return 0;
}

// The time the paper's speed-up divides: its timed region when the algorithm marks one.
double timed_s(const nlohmann::json& r) {
  return r.contains("timed_s") ? r["timed_s"].get<double>() : r["virtual_time_s"].get<double>();
}

double kurc_render_s(const nlohmann::json& r) {
  return phase_s(r, "span_list_creation") + phase_s(r, "local_zbuffer") +
         phase_s(r, "pixel_merging");
}

} // namespace

// Charles et al. §6, Fig. 7: on 16 hypercube nodes the skull "goes faster" than the teapot (8.3),
// "even if the communication time is not preponderant regarding of computing time of the Zbuffer",
// and the ring falls behind the hypercube ("the difference of acceleration between the two
// topologies are more important").
TEST(PaperClaims, DISABLED_CharlesSkullBeatsTeapotOn16CubeNodesAndRingTrails) {
  const auto seq_skull = run("ipsc860", 1, "sequential", "scenes/bone.json", 512);
  const auto seq_pot = run("ipsc860", 1, "sequential", "scenes/teapot.json", 512);
  const auto skull = run("ipsc860", 16, "elastic", "scenes/bone.json", 512);
  const auto pot = run("ipsc860", 16, "elastic", "scenes/teapot.json", 512);
  const auto ring = run("ipsc860", 16, "elastic", "scenes/bone.json", 512, Topology::Ring);
  for (const auto* r : {&seq_skull, &seq_pot, &skull, &pot, &ring})
    ASSERT_EQ((*r)["status"], "ok") << r->dump();
  const double su_skull = timed_s(seq_skull) / timed_s(skull);
  const double su_pot = timed_s(seq_pot) / timed_s(pot);
  const double su_ring = timed_s(seq_skull) / timed_s(ring);
  EXPECT_GT(su_skull, su_pot) << "skull " << su_skull << " teapot " << su_pot;
  EXPECT_LT(su_ring, su_skull) << "ring " << su_ring << " cube " << su_skull;
  double comm = 0;
  for (const char* p : {"multibroadcast_vertices", "multireduce_load", "multiscatter_triangles"})
    comm += phase_s(skull, p);
  EXPECT_LT(comm, phase_s(skull, "zbuffer"))
      << "communication " << comm << " s against the z-buffer's " << phase_s(skull, "zbuffer");
}

// Kurc et al. §5, Table 2 and the conclusions: active merging with the modified scanline z-buffer
// beats full z-buffer merging in both the local z-buffer and the merging phases, and all-to-all
// personalized communication merges faster than the pairwise exchange.
TEST(PaperClaims, DISABLED_KurcActiveMergingBeatsFullMergingAndAapcBeatsPair) {
  std::map<std::string, nlohmann::json> r;
  for (const char* s : {"zbuf-exc", "pair-rs", "pair-hbp", "aapc-rs", "aapc-hbp"}) {
    r[s] = run("ipsc2", 16, s, "scenes/kurc/2pot.json", 400);
    ASSERT_EQ(r[s]["status"], "ok") << r[s].dump();
  }
  EXPECT_LT(phase_s(r["pair-rs"], "local_zbuffer"), phase_s(r["zbuf-exc"], "local_zbuffer"));
  EXPECT_LT(phase_s(r["pair-rs"], "pixel_merging"), phase_s(r["zbuf-exc"], "pixel_merging"));
  EXPECT_LT(phase_s(r["aapc-rs"], "pixel_merging"), phase_s(r["pair-rs"], "pixel_merging"));
  EXPECT_LT(phase_s(r["aapc-hbp"], "pixel_merging"), phase_s(r["pair-hbp"], "pixel_merging"));
  EXPECT_LT(kurc_render_s(r["aapc-hbp"]), kurc_render_s(r["zbuf-exc"]));
}

// Kurc et al. §5: some Table 2 cases "could not be obtained due to insufficient local memory", and
// the 8-node section has no 8 POT_2 row at all. Out of memory must come out of the model: the
// full z-buffer exchange on 8 nodes of 4 MB, with NX/2 resident, does not fit, while the same
// scene fits on 16 nodes (every 16-node figure is printed).
TEST(PaperClaims, DISABLED_KurcAnEightNodeConfigurationRunsOutOfLocalMemory) {
  const auto r8 = run("ipsc2", 8, "zbuf-exc", "scenes/kurc/8pot_2.json", 400);
  EXPECT_EQ(r8["status"], "out_of_memory") << r8.dump().substr(0, 400);
  const auto r16 = run("ipsc2", 16, "zbuf-exc", "scenes/kurc/8pot_2.json", 400);
  EXPECT_EQ(r16["status"], "ok") << r16.value("error", "");
}

// Blazek 1991 ch. VI: "The node initiated method yielded the best results of all four methods";
// host initiated "yields very poor results due to the host-to-node communications bottleneck"; the
// broadcast method "yielded very good results, though not quite as good as the node initiated".
// Checked at 64 spheres (524,288 polygons) on 32 nodes, where every method has work on every node
// (the thesis's 2048 spheres take minutes of host time a method). The thesis also puts broadcast
// ahead of object forwarding; the model does not, for a reason measured and derived in
// docs/papers.md ("Blazek's ranking"), so that pair is not asserted.
TEST(PaperClaims, BlazekNodeInitiatedBestHostInitiatedWorst) {
  std::map<std::string, double> t;
  for (const char* m : {"node-initiated", "host-broadcast", "object-forwarding", "host-initiated"}) {
    SimConfig c;
    c.machine = "ipsc2";
    c.nodes = 32;
    c.algorithm = m;
    c.scene_path = kRoot + "/scenes/blazek/thesis_spheres_64.json";
    c.width = c.height = 512;
    c.compare_with_sequential = false;
    c.overrides.memory_bytes = 16.0 * 1048576; // ch. IV: "up to sixteen megabytes"
    if (std::string(m) == "host-initiated") c.options.values["packet"] = "100";
    const auto r = run_simulation_isolated(c);
    ASSERT_EQ(r["status"], "ok") << m << ": " << r.value("error", "");
    t[m] = timed_s(r);
  }
  EXPECT_LT(t["node-initiated"], t["host-broadcast"]);
  EXPECT_LT(t["node-initiated"], t["object-forwarding"]);
  EXPECT_LT(t["host-broadcast"], t["host-initiated"]);
  EXPECT_LT(t["object-forwarding"], t["host-initiated"]);
}
