// sim/platform_load: a user-edited platform file's figures, host speeds and routes are the machine.
#include <bit>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <unistd.h>

#include <gtest/gtest.h>
#include <simgrid/s4u.hpp>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "machine/topology.hpp"
#include "machine/units.hpp"
#include "sim/platform_load.hpp"
#include "sim_fixtures.hpp"
#include "util/error.hpp"

using namespace zc;
using namespace zc::test;

namespace {

// The platform text of a built-in machine with `from` replaced by `to`, written to a file.
std::string edited_platform(const std::string& machine, int P, Topology topo,
                            const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string x = platform_xml(machine_spec(machine), P, topo);
  for (const auto& [from, to] : edits) {
    const auto at = x.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) x.replace(at, from.size(), to);
  }
  static int serial = 0;
  const auto path =
      std::filesystem::temp_directory_path() /
      ("zcube-test-edited-" + std::to_string(::getpid()) + "-" + std::to_string(serial++) + ".xml");
  std::ofstream(path) << x;
  return path.string();
}

} // namespace

TEST(Platforms, SimGridFiguresOfAUserEditedFileAreTheMachine) {
  const NetworkParams& n = machine_spec("ipsc860").net;
  // Channel bandwidth / 10, channel latency (the per-hop cost) 10 us -> 30 us, the short
  // protocol's start-up (SMPI's receive overhead) + 1 ms: each changes the time as in SimGrid.
  const std::string path =
      edited_platform("ipsc860", 4, Topology::Cube,
                      {{"bw=\"2777777.777777778Bps\"", "bw=\"277777.7777777778Bps\""},
                       {"lat=\"10000ns\"", "lat=\"30us\""},
                       {"value=\"0:5.9239999999999995e-05:0;", "value=\"0:0.00105924:0;"}});
  RunConfig c = sim_config(path, 0, Topology::Cube, Fidelity::Circuit); // P from the file
  auto t = one_way(c, "3", "10B,1000B");
  std::filesystem::remove(path);
  const double per_byte = 10 * n.per_byte_s, hop = 30e-6, envelope = 16 * (per_byte - n.per_byte_s);
  // start-up = smpi/or + lat + 16 bytes / bw: the edited latency and rate enter it as in SMPI.
  expect_rel(t.at({10.0, 2}), 1e-3 + n.startup_short_s + envelope + 20e-6 + 10 * per_byte + hop,
             1e-9, "edited short");
  expect_rel(t.at({1000.0, 2}), n.startup_long_s + envelope + 20e-6 + 1000 * per_byte + hop, 1e-9,
             "edited long");
}

TEST(Platforms, HostSpeedIsTheClockThatScalesCompute) {
  RunConfig s = sim_config("ipsc2", 1, Topology::Cube, Fidelity::Circuit);
  s.algorithm = "sequential";
  s.scene_path = std::string(ZCUBE_SOURCE_DIR) + "/scenes/teapot.json";
  s.width = s.height = 64;
  const double t16 = vtime(run_simulation_isolated(s));
  s.machine =
      edited_platform("ipsc2", 1, Topology::Cube, {{"speed=\"16Mf\" bw", "speed=\"160Mf\" bw"}});
  s.nodes = 0;
  const double t160 = vtime(run_simulation_isolated(s));
  std::filesystem::remove(s.machine);
  expect_rel(t160, t16 / 10, 1e-12, "10x the clock, a tenth of the time");
}

TEST(Platforms, SimGridRoutesAreTheTopologyRoutes) {
  // Every route SimGrid computes from the file (a torus: dimension order) is the route zcube's
  // circuit fidelity holds (topology.cpp): e-cube on the cube, the shorter way on the ring
  // (clockwise on a tie, but for one pair).
  for (auto [P, topo] :
       {std::pair{32, Topology::Cube}, std::pair{1024, Topology::Cube},
        std::pair{7, Topology::Ring}, std::pair{8, Topology::Ring}, std::pair{2, Topology::Ring}}) {
    RunConfig c = sim_config("ipsc2", P, topo, Fidelity::Analytic);
    auto r = run_custom(c, [P, topo](NodeContext& ctx) {
      const int me = ctx.comm().rank();
      if (P > 64 && me % 97 != 0) return; // a sample of sources on the big cube
      auto* self = simgrid::s4u::Host::current();
      auto* e = simgrid::s4u::Engine::get_instance();
      for (int d = 0; d < P; ++d) {
        std::vector<simgrid::s4u::Link*> links;
        self->route_to(e->host_by_name(node_host_name(d)), links, nullptr);
        // One known difference: on an even ring SimGrid goes from P/2 to 0 counter-clockwise,
        // zcube (and the papers' figures) clockwise; the hop count is the same.
        if (topo == Topology::Ring && P % 2 == 0 && me == P / 2 && d == 0) continue;
        const auto want = route(topo, P, me, d);
        if (links.size() != want.size())
          throw std::runtime_error("route " + std::to_string(me) + "->" + std::to_string(d) + ": " +
                                   std::to_string(links.size()) + " links");
        for (std::size_t i = 0; i < want.size(); ++i) {
          // Torus link of the lower node of the pair in that dimension (UP: away from it).
          auto [a, b] = want[i];
          const std::string name = links[i]->get_name();
          const bool ok =
              name.find("_from_" + std::to_string(a) + "_to_" + std::to_string(b) + "_UP") !=
                  name.npos ||
              name.find("_from_" + std::to_string(b) + "_to_" + std::to_string(a) + "_DOWN") !=
                  name.npos;
          if (!ok)
            throw std::runtime_error("route " + std::to_string(me) + "->" + std::to_string(d) +
                                     " hop " + std::to_string(i) + ": " + name);
        }
      }
    });
    EXPECT_EQ(r["status"], "ok") << P << " " << topology_name(topo) << ": " << r.value("error", "");
  }
}

// A batch's parent checks each platform file once and its forked simulations skip the checks
// for the same text: a file edited after its check (same path, new text) is checked again.
TEST(Platforms, AFileEditedAfterItsCheckIsCheckedAgain) {
  const std::string path = edited_platform("ipsc2", 4, Topology::Cube, {});
  ASSERT_NO_THROW(check_platform_file(path));
  ASSERT_NO_THROW(check_platform_file(path)); // the same text: skipped, still fine
  std::string x = platform_xml(machine_spec("ipsc2"), 4, Topology::Cube);
  const auto at = x.find("bw=\"");
  ASSERT_NE(at, std::string::npos);
  const auto end = x.find('"', at + 4);
  x.replace(at, end + 1 - at, "bw=\"2.8\""); // a bare number: no unit
  std::ofstream(path) << x;
  try {
    check_platform_file(path);
    ADD_FAILURE() << "an edited file with a bare bandwidth was not checked again";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}
