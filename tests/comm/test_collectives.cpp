// comm/collectives: the right data on cubes and rings of every size, and closed-form times
// under the analytic fidelity.
#include <bit>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <unistd.h>

#include <gtest/gtest.h>
#include <simgrid/s4u.hpp>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"
#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "machine/topology.hpp"
#include "machine/units.hpp"
#include "sim_fixtures.hpp"
#include "util/error.hpp"

using namespace zc;
using namespace zc::test;

namespace {

// The comm-check algorithm (algo/tools/comm_check: the same self-test runs under MPI, tests/mpi) on
// a simulated machine.
void expect_all_good(RunConfig c, int P) {
  c.algorithm = "comm-check";
  const auto rep = run_simulation_isolated(c);
  ASSERT_EQ(rep["status"], "ok") << rep.dump();
  ASSERT_EQ(int(rep["per_node"].size()), P);
  for (const auto& n : rep["per_node"])
    EXPECT_TRUE(n["metrics"]["comm_check_failures"].empty()) << n.dump();
}

} // namespace

TEST(Collectives, DeliverTheRightDataOnRingsOfEverySize) {
  for (int P = 2; P <= 16; ++P) {
    auto r = run_custom(
        sim_config("ipsc860", P, Topology::Ring, Fidelity::Circuit), [](NodeContext& ctx) {
          Comm& c = ctx.comm();
          const int p = c.size(), k = c.rank();
          int bad = 0;
          for (int root : {0, p - 1, p / 2}) {
            bad += coll::broadcast(c, root, Bytes(k == root ? 9 : 0, 7)) != Bytes(9, 7);
            std::vector<Bytes> parts;
            if (k == root)
              for (int i = 0; i < p; ++i)
                parts.push_back(Bytes(std::size_t(i + 1), std::uint8_t(i)));
            bad += coll::scatterv(c, root, parts) != Bytes(std::size_t(k + 1), std::uint8_t(k));
            auto g = coll::gatherv(c, root, Bytes(std::size_t(k), 1));
            if (k == root)
              for (int i = 0; i < p; ++i)
                bad += g.at(i) != Bytes(std::size_t(i), 1);
            auto red = coll::reduce(c, root, std::vector<double>{double(k)}, coll::Op::Max);
            if (k == root) bad += red != std::vector<double>{double(p - 1)};
          }
          auto all = coll::allgatherv(c, Bytes(1, std::uint8_t(k)));
          for (int i = 0; i < p; ++i)
            bad += all.at(i) != Bytes(1, std::uint8_t(i));
          bad += coll::allreduce(c, std::vector<std::int64_t>{k}, coll::Op::Sum) !=
                 std::vector<std::int64_t>{p * (p - 1) / 2};
          bad += coll::prefix_sum(c, std::vector<std::int64_t>{2}) !=
                 std::vector<std::int64_t>{2 * (k + 1)};
          for (auto how : {coll::AllToAll::Direct, coll::AllToAll::Pairwise}) {
            std::vector<Bytes> out;
            for (int i = 0; i < p; ++i)
              out.push_back(Bytes(std::size_t(i % 3), std::uint8_t(k)));
            auto in = coll::alltoallv(c, out, how);
            for (int i = 0; i < p; ++i)
              bad += in.at(i) != Bytes(std::size_t(k % 3), std::uint8_t(i));
          }
          ctx.metrics()["bad"] = bad;
        });
    ASSERT_EQ(r["status"], "ok") << "P=" << P << " " << r.dump();
    for (const auto& n : r["per_node"])
      EXPECT_EQ(n["metrics"]["bad"], 0) << "ring P=" << P << " " << n.dump();
  }
}

TEST(Collectives, MoreClosedFormTimesUnderAnalytic) {
  // iPSC/860: two protocols and a per-hop term, so the forms are not all the same number.
  const NetworkParams& n = machine_spec("ipsc860").net;
  auto T = [&](double m, int h = 1) { return n.message_time(m, h); };
  for (int P : {2, 4, 16, 32}) {
    const int d = log2_exact(P);
    const std::string at = " P=" + std::to_string(P);
    auto cfg = sim_config("ipsc860", P, Topology::Cube, Fidelity::Analytic);
    const double b = 500; // block bytes
    // Scatter and gather: recursive halving / doubling, 2^i blocks of (12-byte header + b) at
    // the step over dimension i, plus a 4-byte count.
    double blocks = 0;
    for (int i = 0; i < d; ++i)
      blocks += T(4 + (1 << i) * (12 + b));
    expect_rel(vtime(run_custom(cfg,
                                [&](NodeContext& ctx) {
                                  std::vector<Bytes> parts;
                                  if (ctx.rank() == 0) parts.assign(P, Bytes(std::size_t(b)));
                                  coll::scatterv(ctx.comm(), 0, parts);
                                })),
               blocks, 1e-12, "scatterv" + at);
    expect_rel(
        vtime(run_custom(
            cfg, [&](NodeContext& ctx) { coll::gatherv(ctx.comm(), 0, Bytes(std::size_t(b))); })),
        blocks, 1e-12, "gatherv" + at);
    // Reduce (binomial tree) and prefix sum (recursive doubling): d messages of the vector.
    expect_rel(vtime(run_custom(cfg,
                                [&](NodeContext& ctx) {
                                  coll::reduce(ctx.comm(), 0, std::vector<double>(100, 1.0),
                                               coll::Op::Min);
                                })),
               d * T(800), 1e-12, "reduce" + at);
    expect_rel(vtime(run_custom(cfg,
                                [&](NodeContext& ctx) {
                                  coll::prefix_sum(ctx.comm(), std::vector<std::int64_t>(10, 1));
                                })),
               d * T(80), 1e-12, "prefix_sum" + at);
    // All-to-all, pairwise: step k exchanges with rank^k over popcount(k) hops.
    double pw = 0;
    for (int k = 1; k < P; ++k)
      pw += T(b, std::popcount(unsigned(k)));
    auto a2a = [&](coll::AllToAll how) {
      return vtime(run_custom(cfg, [&, how](NodeContext& ctx) {
        coll::alltoallv(ctx.comm(), std::vector<Bytes>(P, Bytes(std::size_t(b))), how);
      }));
    };
    expect_rel(a2a(coll::AllToAll::Pairwise), pw, 1e-12, "alltoall pairwise" + at);
    // Direct: every message at once, no contention: the farthest one ends it.
    expect_rel(a2a(coll::AllToAll::Direct), T(b, d), 1e-12, "alltoall direct" + at);
  }
  // Ring broadcast: two arms from the root, the longer one has P/2 neighbour steps.
  const NetworkParams& v = machine_spec("volvox").net;
  for (int P : {2, 5, 8, 16})
    expect_rel(vtime(run_custom(sim_config("volvox", P, Topology::Ring, Fidelity::Analytic),
                                [](NodeContext& ctx) {
                                  coll::broadcast(ctx.comm(), 1, Bytes(ctx.rank() == 1 ? 2000 : 0));
                                })),
               (P / 2) * v.message_time(2000, 1), 1e-12, "ring broadcast P=" + std::to_string(P));
}

TEST(Collectives, DeliverTheRightDataOnCubes) {
  for (int P : {1, 2, 4, 8, 16, 32})
    expect_all_good(sim_config("ipsc860", P, Topology::Cube, Fidelity::Circuit), P);
}

TEST(Collectives, DeliverTheRightDataOnRings) {
  for (int P : {2, 3, 4, 5, 8, 16})
    expect_all_good(sim_config("volvox", P, Topology::Ring, Fidelity::Flow), P);
}

TEST(Collectives, ClosedFormTimesUnderAnalytic) {
  const NetworkParams& n = machine_spec("ipsc2").net;
  for (int P : {2, 8, 32}) {
    const int d = log2_exact(P);
    const std::size_t m = 4000;
    auto bc = run_custom(
        sim_config("ipsc2", P, Topology::Cube, Fidelity::Analytic),
        [&](NodeContext& ctx) { coll::broadcast(ctx.comm(), 0, Bytes(ctx.rank() == 0 ? m : 0)); });
    expect_rel(bc["virtual_time_s"].get<double>(), d * n.message_time(double(m), 1), 1e-12,
               "broadcast P=" + std::to_string(P));
    // Multi-reduce by recursive doubling: d exchanges of the whole vector.
    auto ar = run_custom(
        sim_config("ipsc2", P, Topology::Cube, Fidelity::Analytic), [&](NodeContext& ctx) {
          coll::allreduce(ctx.comm(), std::vector<std::int64_t>(512, 1), coll::Op::Sum);
        });
    expect_rel(ar["virtual_time_s"].get<double>(), d * n.message_time(512 * 8, 1), 1e-12,
               "allreduce P=" + std::to_string(P));
    // Multi-broadcast: step i carries 2^i blocks (4-byte count, 12-byte header per block).
    const std::size_t b = 1000;
    auto ag = run_custom(sim_config("ipsc2", P, Topology::Cube, Fidelity::Analytic),
                         [&](NodeContext& ctx) { coll::allgatherv(ctx.comm(), Bytes(b)); });
    double want = 0;
    for (int i = 0; i < d; ++i)
      want += n.message_time(4.0 + (1 << i) * (12.0 + b), 1);
    expect_rel(ag["virtual_time_s"].get<double>(), want, 1e-12, "allgather P=" + std::to_string(P));
  }
}
