#pragma once
// Running simulations from tests: every simulation in its own forked process (SimGrid allows one
// engine per process), with a test-defined algorithm when needed.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <memory>

#include <nlohmann/json.hpp>

#include "sim/simulation.hpp"

namespace zc::test {

// |got - want| within tol of |want| (relative), with a message naming the case.
inline void expect_rel(double got, double want, double tol, const std::string& what) {
  EXPECT_LE(std::fabs(got - want), tol * std::max(std::fabs(want), 1e-300))
      << what << ": got " << got << " want " << want;
}

inline RunConfig sim_config(const std::string& machine, int nodes, Topology topo, Fidelity fid) {
  RunConfig c;
  c.machine = machine;
  c.nodes = nodes;
  c.topology = topo;
  c.fidelity = fid;
  c.compare_with_sequential = false;
  return c;
}

inline nlohmann::json run_custom(RunConfig cfg, std::function<void(NodeContext&)> node) {
  auto a = std::make_shared<Algorithm>();
  a->name = "test";
  a->node = std::move(node);
  cfg.custom = a;
  return run_simulation_isolated(cfg);
}

// A run's virtual time, after checking that the run succeeded.
inline double vtime(const nlohmann::json& r) {
  EXPECT_EQ(r["status"], "ok") << r.dump();
  return r["virtual_time_s"].get<double>();
}

// One-way times of a ping-pong from node 0, indexed by (bytes, hops).
inline std::map<std::pair<double, int>, double>
one_way(const RunConfig& base, const std::string& to, const std::string& sizes) {
  RunConfig c = base;
  c.algorithm = "pingpong";
  c.options.values = {{"from", "0"}, {"to", to}, {"sizes", sizes}};
  auto r = run_simulation_isolated(c);
  EXPECT_EQ(r["status"], "ok") << r.dump();
  std::map<std::pair<double, int>, double> t;
  for (const auto& x : r["results"])
    t[{x["bytes"].get<double>(), x["hops"].get<int>()}] = x["one_way_s"].get<double>();
  return t;
}

} // namespace zc::test
