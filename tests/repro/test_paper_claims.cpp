// The papers' qualitative statements, checked on the calibrated machine models at small sizes
// where each statement holds. These are claims about the model, not about
// the fit: a check that fails after a re-calibration says the refit broke a published statement.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "repro/paper_figures.hpp"
#include "repro/reproduce.hpp" // timed_s: the time every speed-up divides
#include "sim/simulation.hpp"
#include "source_root.hpp"

using namespace zc;

namespace {

using test::kRoot;

nlohmann::json run(const std::string& machine, int nodes, const std::string& algorithm,
                   const std::string& scene, int size, Topology topo = Topology::Cube) {
  RunConfig c;
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

double kurc_render_s(const nlohmann::json& r) {
  return phase_s(r, "span_list_creation") + phase_s(r, "local_zbuffer") +
         phase_s(r, "pixel_merging");
}

} // namespace

// Charles et al. §6, Fig. 7 on 16 iPSC/860 nodes, 512x512: the skull stand-in against the teapot,
// hypercube against ring. Run once for the three checks below.
struct CharlesRuns {
  nlohmann::json seq_skull, seq_pot, skull, pot, ring;
  static const CharlesRuns& get() {
    static const CharlesRuns r = [] {
      CharlesRuns c;
      c.seq_skull = run("ipsc860", 1, "sequential", "scenes/bone.json", 512);
      c.seq_pot = run("ipsc860", 1, "sequential", kCharlesTeapotScene, 512);
      c.skull = run("ipsc860", 16, "elastic", "scenes/bone.json", 512);
      c.pot = run("ipsc860", 16, "elastic", kCharlesTeapotScene, 512);
      c.ring = run("ipsc860", 16, "elastic", "scenes/bone.json", 512, Topology::Ring);
      return c;
    }();
    return r;
  }
  void expect_ok() const {
    for (const auto* r : {&seq_skull, &seq_pot, &skull, &pot, &ring})
      ASSERT_EQ((*r)["status"], "ok") << r->dump();
  }
};

// "the communication time is not preponderant regarding of computing time of the Zbuffer". Holds
// once the network is charged §4's 16-byte projected vertex (records.hpp) instead of zcube's
// 28-byte payload: communication 0.269 s against a 0.324 s z-buffer (it was 0.433 s at 28 bytes;
// docs/papers.md, "Records").
TEST(PaperClaims, CharlesSkullCommunicationBelowItsZbuffer) {
  const auto& c = CharlesRuns::get();
  c.expect_ok();
  double comm = 0;
  for (const char* p : {"multibroadcast_vertices", "multireduce_load", "multiscatter_triangles"})
    comm += phase_s(c.skull, p);
  EXPECT_LT(comm, phase_s(c.skull, "zbuffer"))
      << "communication " << comm << " s against the z-buffer's " << phase_s(c.skull, "zbuffer");
}

// "the difference of acceleration between the two topologies are more important" (ring below).
TEST(PaperClaims, CharlesSkullRingBelowHypercube) {
  const auto& c = CharlesRuns::get();
  c.expect_ok();
  EXPECT_LT(timed_s(c.seq_skull) / timed_s(c.ring), timed_s(c.seq_skull) / timed_s(c.skull));
}

// "When we use an hypercube of 16 processors we go [held out] times faster while the speed-up of
// the teapot is limited to 8.3". Not reproduced: the stand-in carries well under half the
// teapot's work per vertex on the wire (smaller triangles), and no plausible CPU or network
// setting reverses the order (docs/papers.md, "Charles's skull against the teapot"; the what-ifs
// that showed it in CHANGELOG.md). Disabled for that documented reason; never tuned to the
// held-out figure.
TEST(PaperClaims, DISABLED_CharlesSkullSpeedupAboveTeapotOn16CubeNodes) {
  const auto& c = CharlesRuns::get();
  c.expect_ok();
  const double su_skull = timed_s(c.seq_skull) / timed_s(c.skull);
  const double su_pot = timed_s(c.seq_pot) / timed_s(c.pot);
  EXPECT_GT(su_skull, su_pot) << "skull " << su_skull << " teapot " << su_pot;
}

// Kurc et al. §5, Table 2 and the conclusions, 2 POT at 400x400 on 16 nodes.
struct KurcRuns {
  std::map<std::string, nlohmann::json> r;
  static const KurcRuns& get() {
    static const KurcRuns k = [] {
      KurcRuns x;
      for (const char* s : {"zbuf-exc", "pair-rs", "pair-hbp", "aapc-rs", "aapc-hbp"})
        x.r[s] = run("ipsc2", 16, s, "scenes/kurc/2pot.json", 400);
      return x;
    }();
    return k;
  }
  const nlohmann::json& at(const char* s) const {
    const auto& j = r.at(s);
    EXPECT_EQ(j["status"], "ok") << j.dump();
    return j;
  }
};

// "PAIR-RS gives much better results than ZBUF-EXC in pixel merging phase ... PAIR-RS performs
// better than ZBUF-EXC also in local z-buffer phase since it avoids initialization of z-buffer".
TEST(PaperClaims, KurcModifiedScanlineZbufferBeatsFullMerging) {
  const auto& k = KurcRuns::get();
  EXPECT_LT(phase_s(k.at("pair-rs"), "local_zbuffer"), phase_s(k.at("zbuf-exc"), "local_zbuffer"));
  EXPECT_LT(phase_s(k.at("pair-rs"), "pixel_merging"), phase_s(k.at("zbuf-exc"), "pixel_merging"));
  EXPECT_LT(kurc_render_s(k.at("aapc-hbp")), kurc_render_s(k.at("zbuf-exc")));
}

// "all-to-all personalized communication scheme achieves less communication overhead than
// pairwise exchange scheme due to less store-and-forward overheads": less volume (Fig. 1) with
// either screen partition, and a faster merge for the recommended AAPC-HBP. (AAPC-RS against
// PAIR-RS is within 2 % in time and goes either way with the start-up and merge prices: a
// statement about the fit, not checked here.)
TEST(PaperClaims, KurcAapcMergesWithLessOverheadThanPair) {
  const auto& k = KurcRuns::get();
  auto volume = [&](const char* s) {
    return k.at(s)["communication"]["concurrent_volume_bytes"].get<double>();
  };
  EXPECT_LT(volume("aapc-rs"), volume("pair-rs"));
  EXPECT_LT(volume("aapc-hbp"), volume("pair-hbp"));
  EXPECT_LT(phase_s(k.at("aapc-hbp"), "pixel_merging"), phase_s(k.at("pair-hbp"), "pixel_merging"));
}

// Kurc et al. §5: some Table 2 cases "could not be obtained due to insufficient local memory", and
// the 8-node section has no 8 POT_2 row. Out of memory must come out of the model. Disabled with
// the measured reason (docs/memory.md, "Kurc's asterisks"): with the paper's records the 8-node
// peak is 2,474,360 bytes (16 nodes: 2,339,360) of 4,194,304; the sentence needs NX/2 and the
// program (R) plus early-message buffers (B) in (2,244,232, 2,379,232] bytes, R in (1.61, 1.73]
// MiB even with the partner's half system-buffered, beyond R's 256 KiB - 1 MiB. Only charging
// three buffers the paper does not describe (that half, a packed send buffer, span lists kept)
// brings R into its range.
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
// docs/papers.md ("Blazek's ranking"), so that pair is not asserted. Run once for both checks.
struct BlazekRuns {
  std::map<std::string, double> t;
  static const BlazekRuns& get() {
    static const BlazekRuns b = [] {
      BlazekRuns x;
      std::map<std::string, double>& t = x.t;
      for (const char* m :
           {"node-initiated", "host-broadcast", "object-forwarding", "host-initiated"}) {
        RunConfig c;
        c.machine = "ipsc2";
        c.nodes = 32;
        c.algorithm = m;
        c.scene_path = kRoot + "/scenes/blazek/thesis_spheres_64.json";
        c.width = c.height = 512;
        c.compare_with_sequential = false;
        c.what_ifs.set("memory", {16.0 * 1048576}); // ch. IV: "up to sixteen megabytes"
        if (std::string(m) == "host-initiated") c.options.values["packet"] = "100";
        const auto r = run_simulation_isolated(c);
        EXPECT_EQ(r["status"], "ok") << m << ": " << r.value("error", "");
        t[m] = timed_s(r);
      }
      return x;
    }();
    return b;
  }
};

TEST(PaperClaims, BlazekNodeInitiatedBestHostInitiatedBelowForwarding) {
  const auto& t = BlazekRuns::get().t;
  EXPECT_LT(t.at("node-initiated"), t.at("host-broadcast"));
  EXPECT_LT(t.at("node-initiated"), t.at("object-forwarding"));
  EXPECT_LT(t.at("object-forwarding"), t.at("host-initiated"));
}

// Host initiated below host broadcast too. Not reproduced since the host's polygon packets are
// charged the thesis's 30 bytes a polygon ("packets containing 100 polygons each ... three
// kilobytes", ch. V) instead of zcube's 80: host initiated 166.7 -> 126.0 s, host broadcast
// 128.9 s (both on the 1 ms, 1 MB/s host link assumption, docs/machines.md; the broadcast's floor
// is every node tessellating every polygon, docs/papers.md "Blazek's ranking"). Disabled for that
// measured reason.
TEST(PaperClaims, DISABLED_BlazekHostBroadcastAheadOfHostInitiated) {
  const auto& t = BlazekRuns::get().t;
  EXPECT_LT(t.at("host-broadcast"), t.at("host-initiated"));
}
