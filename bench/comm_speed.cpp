// Host benchmark of the simulator (not a test: it measures, it checks nothing): process CPU time
// per simulated message and per collective on 32 iPSC/860 nodes, for every fidelity.
//   build/zcube_comm_speed
#include <ctime>
#include <iostream>
#include <memory>

#include "comm/collectives.hpp"
#include "sim/simulation.hpp"

using namespace zc;

int main() {
  for (Fidelity f : {Fidelity::Analytic, Fidelity::Flow, Fidelity::Circuit}) {
    RunConfig cfg;
    cfg.machine = "ipsc860";
    cfg.nodes = 32;
    cfg.fidelity = f;
    cfg.compare_with_sequential = false;
    auto a = std::make_shared<Algorithm>();
    a->name = "comm-speed";
    a->node = [](NodeContext& ctx) {
      // Process CPU time (user + system): the machine may be shared, and the simulation runs in
      // one thread, so this is the wall time it takes on an otherwise idle core.
      struct clk {
        using time_point = double;
        static double now() { return double(std::clock()) / CLOCKS_PER_SEC; }
      };
      Comm& c = ctx.comm();
      const int P = c.size(), d = c.dimension(), me = c.rank();
      auto lap = [&](clk::time_point t0, double n) { return (clk::now() - t0) / n; };
      nlohmann::json& m = ctx.metrics();
      coll::barrier(c);
      auto t0 = clk::now();
      const int rounds = 20;
      for (int i = 0; i < rounds; ++i) { // every node exchanges 1 KB with a neighbour
        const int partner = me ^ (1 << (i % d));
        auto h = c.isend(partner, 1, Bytes(1024));
        c.recv(partner, 1);
        h->wait();
      }
      coll::barrier(c);
      if (me == 0) m["message_s"] = lap(t0, double(rounds) * P);
      const int K = 3;
      auto time = [&](const char* name, auto fn) {
        coll::barrier(c);
        auto t = clk::now();
        for (int k = 0; k < K; ++k)
          fn();
        coll::barrier(c);
        if (me == 0) m[name] = lap(t, K);
      };
      time("broadcast_1KB_s", [&] { coll::broadcast(c, 0, Bytes(me == 0 ? 1024 : 0)); });
      time("allreduce_64_doubles_s",
           [&] { coll::allreduce(c, std::vector<double>(64, 1.0), coll::Op::Sum); });
      time("allgatherv_256B_s", [&] { coll::allgatherv(c, Bytes(256)); });
      time("alltoallv_pairwise_256B_s", [&] {
        coll::alltoallv(c, std::vector<Bytes>(P, Bytes(256)), coll::AllToAll::Pairwise);
      });
      time("alltoallv_direct_256B_s",
           [&] { coll::alltoallv(c, std::vector<Bytes>(P, Bytes(256)), coll::AllToAll::Direct); });
    };
    cfg.custom = a;
    const auto r = run_simulation_isolated(cfg);
    if (r["status"] != "ok") {
      std::cerr << "comm_speed: " << r.dump() << "\n";
      return 1;
    }
    const auto& m = r["per_node"][0]["metrics"];
    std::cout << "[speed] ipsc860 32 nodes " << fidelity_name(f) << ":";
    for (auto& [k, v] : m.items())
      std::cout << " " << k << "=" << v.get<double>() * 1e6 << "us";
    std::cout << "\n";
  }
  return 0;
}
