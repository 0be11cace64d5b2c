#include "sim/simulation.hpp"

#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

#include <simgrid/s4u.hpp>
#include <xbt/config.hpp>

#include "machine/clock_limits.hpp"
#include "machine/platform_xml.hpp"
#include "machine/units.hpp"
#include "run/batch.hpp"
#include "run/report.hpp"
#include "run/run_steps.hpp"
#include "run/sim_cost.hpp"
#include "sim/platform_load.hpp"
#include "sim/sim_context.hpp"
#include "util/error.hpp"
#include "util/input_file.hpp"

namespace zc {

namespace sg = simgrid::s4u;

namespace {

// The stack of a message's actor under the flow fidelity, in KiB. Its code (a SimGrid transfer)
// ran in 8 KiB with guard pages on, and faulted in 4; SimGrid's debug logging, which formats on
// the actor's stack, ran in 16 and faulted in 8. 16 KiB, or 64 when a run sets any log level.
unsigned message_stack_kib(const std::vector<std::string>& simgrid_args) {
  const bool logs = std::ranges::any_of(
      simgrid_args, [](const std::string& a) { return a.starts_with("--log="); });
  return logs ? 64 : 16;
}

// A rank's stack (contexts/stack-size, 8 MiB) holds the few pages a node program uses. Without
// guard pages (the flow fidelity) SimGrid allocates it zeroed: on fresh pages (glibc's mmap) that
// costs nothing, but once a larger buffer freed earlier has raised glibc's dynamic mmap threshold
// above the stack's size, the stack comes from the heap and is cleared page by page (2,048 page
// faults a rank). The threshold is fixed at the stack's size, so stacks stay on fresh pages;
// smaller buffers stay on the heap, whose top is trimmed only past twice that, as the dynamic rule
// would.
void keep_stacks_on_fresh_pages() {
  const long stack = long(simgrid::config::get_value<int>("contexts/stack-size")) * 1024;
  if (stack < (1L << 20)) return; // a small stack is cheap to clear; keep glibc's rule
  mallopt(M_MMAP_THRESHOLD, int(std::min(stack, 32L << 20)));
  mallopt(M_TRIM_THRESHOLD, int(std::min(2 * stack, 64L << 20)));
}

// The machine under one draw of the uncertainty model: every node's costs, the network, the node
// operating system's share.
void apply_model_draw(const ModelDraw& d, PlatformModel& pm) {
  pm.net = apply_draw(pm.net, d);
  for (CostTable& c : pm.cost)
    c = apply_draw(c, d);
  pm.os_resident *= d.os_resident;
}

} // namespace

namespace {

// Where the platform comes from: a built-in machine is generated on the fly for any P (`zcube
// platform` writes the same text), a path is loaded as given.
struct PlatformSource {
  bool is_file = false;
  std::string label, builtin_xml;
  std::vector<std::string> file_settings; // the file's <config>, checked as --cfg is
};

PlatformSource platform_source(const RunConfig& cfg) {
  PlatformSource src;
  src.is_file = is_platform_file(cfg.machine);
  if (src.is_file) {
    check_platform_file(cfg.machine); // before this process has an engine: it tries the file
    src.file_settings = platform_file_settings(cfg.machine);
    src.label = cfg.machine;
    return src;
  }
  check_node_count(cfg.topology, cfg.nodes);
  // --cpu-scale is the host speed clock / k, as `zcube platform --cpu-scale` writes it: a file
  // written with it runs as the flag does, to the bit (costs are cycles / speed either way).
  PlatformEdits edits;
  edits.cpu_scale = cfg.what_ifs.cpu_scale();
  src.builtin_xml = platform_xml(machine_spec(cfg.machine), cfg.nodes, cfg.topology, edits);
  src.label = "zcube platform --machine " + cfg.machine + " --nodes " + std::to_string(cfg.nodes) +
              " --topology " + topology_name(cfg.topology);
  return src;
}

// SimGrid's arguments: zcube's settings, then the platform file's <config>, then the user's --cfg
// and --log (so they win).
std::vector<std::string> engine_args(const RunConfig& cfg, const PlatformSource& src) {
  std::vector<std::string> args = {"zcube",
                                   "--log=root.thres:critical",
                                   "--cfg=network/model:CM02",
                                   "--cfg=network/crosstraffic:0",
                                   "--cfg=network/loopback-lat:0",
                                   "--cfg=maxmin/precision:1e-12"};
  // SimGrid's timing precision is absolute: it must stay above the rounding step of the clock
  // (1e-12 s is, up to ~4000 s of virtual time; 1e-24 made SimGrid miss wake-ups and report a
  // deadlock) and below the shortest events. It scales with --cost-scale, so scaled runs are the
  // same computation with every number multiplied by k.
  args.push_back("--cfg=surf/precision:" + format_double(1e-12 * cfg.what_ifs.cost_scale()));
  // Under the flow fidelity every message is an actor (Delivery::post): SimGrid's guard page on
  // its stack split and merged the heap's mapping on every message. Those runs go without stack
  // guards (the ranks' stacks are 8 MiB, far more than the renderers use);
  // --cfg=contexts/guard-size:1, passed after this, puts them back.
  if (cfg.fidelity == Fidelity::Flow) args.push_back("--cfg=contexts/guard-size:0");
  args.insert(args.end(), src.file_settings.begin(), src.file_settings.end());
  args.insert(args.end(), cfg.simgrid_args.begin(), cfg.simgrid_args.end());
  return args;
}

// The platform loaded into `e`, read back as a model, with the run's what-ifs and its draw of
// the uncertainty model applied.
PlatformModel load_machine(sg::Engine& e, const RunConfig& cfg, const PlatformSource& src) {
  if (src.is_file)
    load_platform_file(e, cfg.machine);
  else
    load_platform_text(e, src.builtin_xml, src.label);
  PlatformModel pm = read_platform(e, src.label);
  if (src.is_file && cfg.nodes != pm.nodes && cfg.nodes != 0)
    throw UsageError("--nodes " + std::to_string(cfg.nodes) + " but " + src.label + " models " +
                     std::to_string(pm.nodes) + " nodes");
  WhatIfs what_ifs = cfg.what_ifs;
  if (!src.is_file) what_ifs.reset("cpu-scale"); // in the built-in machine's host speed already
  apply_what_ifs(what_ifs, pm, e);
  if (cfg.draw) apply_model_draw(*cfg.draw, pm);
  return pm;
}

// How the ranks ended: the first failure's reason, whether it was a node out of its memory, and
// which ranks finished.
struct RankOutcome {
  std::string failure;
  bool oom = false;
  std::vector<char> finished;
};

// Runs every rank (and the host computer's, when the algorithm has one) to its end or the first
// failure, which stops the others.
RankOutcome run_ranks(sg::Engine& e, const Algorithm& algo, const PlatformModel& pm,
                      const std::vector<sg::Host*>& hosts, Delivery& delivery,
                      std::vector<std::unique_ptr<SimContext>>& ctxs,
                      std::vector<NodeStats>& stats) {
  const int P = pm.nodes;
  RankOutcome out;
  out.finished.assign(std::size_t(P + 1), 0);
  // Once the last rank is done (or one failed), no pending wake-up may move the clock further:
  // the run ends at the last rank's end, as SimGrid ends it when only the daemon is left.
  int running = P + (algo.uses_host ? 1 : 0);
  auto body = [&](int r, const std::function<void(NodeContext&)>& fn) {
    try {
      if (r < P && pm.os_resident > 0) ctxs[r]->alloc(pm.os_resident, "node operating system");
      fn(*ctxs[r]);
      out.finished[r] = 1;
      if (--running == 0) delivery.stop();
    } catch (const OutOfNodeMemory& ex) {
      if (out.failure.empty()) out.failure = ex.what();
      out.oom = true;
      delivery.stop();
      sg::Actor::kill_all();
    } catch (const std::exception& ex) {
      if (out.failure.empty()) out.failure = "node " + std::to_string(r) + ": " + ex.what();
      delivery.stop();
      sg::Actor::kill_all();
    }
    stats[r].finish_s = sg::Engine::get_clock();
  };
  for (int r = 0; r < P; ++r)
    sg::Actor::create("node" + std::to_string(r), hosts[r], [&, r] { body(r, algo.node); });
  if (algo.uses_host) sg::Actor::create(kHostComputerName, hosts[P], [&] { body(P, algo.host); });
  e.run();
  return out;
}

// Why a run that ended at `vtime` has no times to report, beyond its ranks' own failures: a rank
// still waiting for a message nobody sends, or a clock past what it resolves.
std::string failure_after_run(const RankOutcome& o, const Algorithm& algo, int P, double vtime,
                              const RunConfig& cfg) {
  for (int r = 0; r <= P; ++r)
    if (!o.finished[r] && (r < P || algo.uses_host))
      return (r < P ? "node " + std::to_string(r) : std::string("host computer")) +
             ": deadlock (still waiting for a message when the simulation ended)";
  // The clock is a double: beyond 2^52 ns (52 days, times --cost-scale) it no longer resolves a
  // nanosecond, and compute phases (a CPU cycle is 25..63 ns) are rounded or vanish when added
  // to it. Such a run has no exact times to report.
  const double clock_limit = kClockResolvedNs * 1e-9 * cfg.what_ifs.cost_scale();
  if (!(vtime <= clock_limit))
    return "virtual time " + format_double(vtime) + " s is beyond " + format_double(clock_limit) +
           " s (2^52 ns), where the simulated clock no longer resolves a nanosecond and compute "
           "times would be rounded; use faster what-if costs";
  return "";
}

// The machine the run was priced on, for the report's "model".
ModelSection model_section(const PlatformModel& pm, const WhatIfs& w) {
  ModelSection m;
  m.net = pm.net;
  m.node_memory_bytes = pm.memory.empty() ? 0.0 : pm.memory[0];
  m.os_resident_bytes = pm.os_resident;
  if (!pm.cost.empty()) m.node0_cpu = pm.cost.front();
  m.what_ifs = w;
  return m;
}

} // namespace

namespace {

// The ranks' records: the P nodes, then the host computer when the algorithm has one.
std::vector<NodeRecord> records_of(const std::vector<std::unique_ptr<SimContext>>& ctxs,
                                   const Algorithm& algo, int P) {
  std::vector<NodeRecord> records;
  for (int r = 0; r < P; ++r)
    records.push_back(ctxs[std::size_t(r)]->record(Recorder::node(r)));
  if (algo.uses_host) records.push_back(ctxs[std::size_t(P)]->record(Recorder::host(P)));
  return records;
}

// The run on SimGrid: the machine loaded into a fresh engine, a context per rank (and one for the
// host computer), the ranks run to their end or the first failure.
// `pm` receives the machine the run was priced on.
Executed execute_on_simgrid(const RunConfig& cfg, const PreparedRun& run, SimCost& sim_cost,
                            PlatformModel& pm) {
  const Algorithm& algo = *run.algo;
  const Scene& scene = run.scene();
  const PlatformSource src = platform_source(cfg);
  std::vector<std::string> args = engine_args(cfg, src);
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  int argc = int(argv.size());
  declare_platform_flags();
  sg::Engine e(&argc, argv.data());
  keep_stacks_on_fresh_pages();
  pm = load_machine(e, cfg, src);
  const int P = pm.nodes;
  if (algo.check_nodes) algo.check_nodes(run.options, P);

  std::vector<sg::Host*> hosts;
  for (int r = 0; r < P; ++r)
    hosts.push_back(e.host_by_name(node_host_name(r)));
  hosts.push_back(e.host_by_name(kHostComputerName));
  SimNetwork net(pm.net, pm.topology, P, cfg.fidelity, hosts, sim_cost);
  Delivery delivery(net, cfg.fidelity, hosts, message_stack_kib(cfg.simgrid_args), sim_cost);
  std::vector<NodeStats> stats(P + 1);
  if (cfg.timeline)
    for (auto& s : stats)
      s.log = std::make_shared<EventLog>();
  std::vector<std::unique_ptr<SimComm>> comms;
  std::vector<std::unique_ptr<SimContext>> ctxs;
  Executed done;
  const SceneFacts facts = scene_facts(scene); // once for all the nodes
  for (int r = 0; r <= P; ++r) {
    comms.push_back(
        std::make_unique<SimComm>(r, P, pm.topology, delivery, stats[r], pm.net.charge_payloads));
    const CostTable cost = r < P ? pm.cost[r] : pm.cost[0];
    const double mem = r < P ? pm.memory[r] : 0.0; // the host computer is not memory-bound
    ctxs.push_back(std::make_unique<SimContext>(*comms[r], stats[r], scene, facts, run.options,
                                                cost, mem, done.images, cfg.draw.get()));
  }
  sim_cost.actors += std::uint64_t(P + (algo.uses_host ? 1 : 0));
  const RankOutcome ranks = run_ranks(e, algo, pm, hosts, delivery, ctxs, stats);
  done.total_s = sg::Engine::get_clock();
  done.failure =
      ranks.failure.empty() ? failure_after_run(ranks, algo, P, done.total_s, cfg) : ranks.failure;
  done.out_of_memory = ranks.oom;
  done.machine = pm.machine;
  done.platform = src.label;
  done.topology = topology_name(pm.topology);
  done.fidelity = fidelity_name(cfg.fidelity);
  done.nodes = P;
  done.records = records_of(ctxs, algo, P);
  return done;
}

} // namespace

RunResult run_simulation(const RunConfig& cfg, const Scene* preloaded, PlatformModel* model) {
  const PreparedRun run =
      prepare_run(cfg, preloaded, is_platform_file(cfg.machine) || cfg.topology == Topology::Cube);
  SimCost sim_cost;
  PlatformModel pm;
  RunResult res = finish_run(cfg, run, execute_on_simgrid(cfg, run, sim_cost, pm));
  if (model) *model = pm;
  res.report.model = model_section(pm, cfg.what_ifs);
  // What the simulation cost in events: the same in every run of this configuration, on any host.
  res.report.simulation_cost = sim_cost;
  return res;
}

nlohmann::json run_simulation_isolated(const RunConfig& cfg) {
  return run_batch({cfg}, 1,
                   [](const RunConfig& c) { return report_json(run_simulation(c).report); })
      .front();
}

} // namespace zc
