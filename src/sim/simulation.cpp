#include "sim/simulation.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>

#include <simgrid/s4u.hpp>

#include "geometry/camera_path.hpp"
#include "machine/platform_xml.hpp"
#include "machine/units.hpp"
#include "raster/image_io.hpp"
#include "raster/renderer.hpp"
#include "repro/paper_figures.hpp"
#include "scene/load.hpp"
#include "sim/batch.hpp"
#include "sim/report.hpp"
#include "sim/sim_context.hpp"
#include "util/error.hpp"

namespace zc {

namespace sg = simgrid::s4u;

namespace {

double prop_number(const char* v, const std::string& key, const std::string& where) {
  if (!v) throw InputError(where, 0, "platform property '" + key + "' is missing");
  char* end = nullptr;
  const double d = std::strtod(v, &end);
  if (end == v || *end != '\0' || !(d >= 0))
    throw InputError(where, 0, "platform property '" + key + "' is not a non-negative number");
  return d;
}

struct PlatformModel {
  std::string machine;
  Topology topology = Topology::Cube;
  int nodes = 0;
  NetworkParams net;
  std::vector<CostTable> cost; // per node
  std::vector<double> memory;  // per node
};

PlatformModel read_platform(const sg::Engine& e, const std::string& where) {
  PlatformModel m;
  const sg::NetZone* z = e.get_netzone_root();
  // The machine zone is the root, or its only child when the file wraps it.
  if (!z->get_property("zcube.machine") && z->get_children().size() == 1) z = z->get_children()[0];
  auto zp = [&](const std::string& k) { return z->get_property(k); };
  if (!zp("zcube.machine"))
    throw InputError(where, 0, "not a zcube platform (no zcube.machine property on its zone)");
  m.machine = zp("zcube.machine");
  m.topology = parse_topology(zp("zcube.topology") ? zp("zcube.topology") : "");
  m.nodes = int(prop_number(zp("zcube.nodes"), "zcube.nodes", where));
  const std::string sw = zp("zcube.switching") ? zp("zcube.switching") : "";
  if (sw != "circuit" && sw != "store-and-forward")
    throw InputError(where, 0, "zcube.switching must be circuit or store-and-forward");
  m.net.switching = sw == "circuit" ? Switching::Circuit : Switching::StoreAndForward;
  auto num = [&](const char* k) { return prop_number(zp(k), k, where); };
  m.net.startup_short_s = num("zcube.startup_short_s");
  m.net.startup_long_s = num("zcube.startup_long_s");
  m.net.short_max_bytes = num("zcube.short_max_bytes");
  m.net.per_byte_s = num("zcube.per_byte_s");
  m.net.per_hop_s = num("zcube.per_hop_s");
  m.net.host_startup_s = num("zcube.host_startup_s");
  m.net.host_per_byte_s = num("zcube.host_per_byte_s");
  for (int r = 0; r < m.nodes; ++r) {
    const sg::Host* h = e.host_by_name_or_null(node_host_name(r));
    if (!h) throw InputError(where, 0, "host '" + node_host_name(r) + "' is missing");
    CostTable t;
    for (auto& [id, v] : t.fields())
      *v = prop_number(h->get_property(id), id, where);
    m.cost.push_back(t);
    m.memory.push_back(prop_number(h->get_property("memory_bytes"), "memory_bytes", where));
  }
  if (!e.host_by_name_or_null(kHostComputerName))
    throw InputError(where, 0, "host 'srm' is missing");
  return m;
}

void apply_overrides(const Overrides& o, PlatformModel& m, sg::Engine& e) {
  auto& n = m.net;
  if (o.latency_s) n.startup_short_s = n.startup_long_s = *o.latency_s;
  if (o.bandwidth_Bps) {
    if (!(*o.bandwidth_Bps > 0)) throw UsageError("--bandwidth must be positive");
    n.per_byte_s = 1.0 / *o.bandwidth_Bps;
  }
  if (o.per_hop_s) n.per_hop_s = *o.per_hop_s;
  if (o.memory_bytes)
    for (auto& mem : m.memory)
      mem = *o.memory_bytes;
  double cpu = o.cpu_scale.value_or(1.0);
  if (o.cost_scale) {
    const double k = *o.cost_scale;
    cpu *= k;
    n.startup_short_s *= k;
    n.startup_long_s *= k;
    n.per_byte_s *= k;
    n.per_hop_s *= k;
    n.host_startup_s *= k;
    n.host_per_byte_s *= k;
  }
  if (cpu != 1.0)
    for (auto& c : m.cost)
      c = c.scaled(cpu);
  // The links carry the per-byte cost under the flow model.
  for (sg::Link* l : e.get_all_links()) {
    const std::string name = l->get_name();
    const double per_byte = name.rfind("host-", 0) == 0 ? n.host_per_byte_s : n.per_byte_s;
    l->set_bandwidth(per_byte > 0 ? 1.0 / per_byte : 1e15);
  }
}

std::string write_temp_platform(const std::string& xml, const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string path = (dir / ("zcube-" + std::to_string(getpid()) + "-" + name)).string();
  std::ofstream(path) << xml;
  return path;
}

} // namespace

SimResult run_simulation(const SimConfig& cfg, const Scene* preloaded) {
  const auto wall0 = std::chrono::steady_clock::now();
  const Algorithm& algo = cfg.custom ? *cfg.custom : find_algorithm(cfg.algorithm);
  for (const auto& [k, v] : cfg.options.values)
    if (std::find(algo.option_keys.begin(), algo.option_keys.end(), k) == algo.option_keys.end())
      throw UsageError("--" + k + " does not apply to algorithm " + algo.name);
  if (cfg.options.frames < 1) throw UsageError("--frames must be at least 1");

  Scene loaded;
  if (!preloaded && !cfg.scene_path.empty()) {
    LoadOptions lo;
    lo.width = cfg.width;
    lo.height = cfg.height;
    loaded = load_scene(cfg.scene_path, lo);
  }
  const Scene& scene = preloaded ? *preloaded : loaded;

  // Platform: a built-in machine is generated on the fly (identical to platforms/), a path is
  // loaded as given.
  std::string platform_path, platform_label, tmp;
  const bool is_file = cfg.machine.size() > 4 && cfg.machine.ends_with(".xml");
  if (is_file) {
    if (!std::filesystem::exists(cfg.machine)) throw InputError(cfg.machine, 0, "file not found");
    platform_path = platform_label = cfg.machine;
  } else {
    check_node_count(cfg.topology, cfg.nodes);
    const std::string name = platform_file_name(cfg.machine, cfg.nodes, cfg.topology);
    tmp = platform_path =
        write_temp_platform(platform_xml(machine_spec(cfg.machine), cfg.nodes, cfg.topology), name);
    platform_label = "platforms/" + name;
  }

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
  args.push_back("--cfg=surf/precision:" +
                 format_double(1e-12 * cfg.overrides.cost_scale.value_or(1.0)));
  args.insert(args.end(), cfg.simgrid_args.begin(), cfg.simgrid_args.end());
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  int argc = int(argv.size());
  sg::Engine e(&argc, argv.data());
  try {
    e.load_platform(platform_path);
  } catch (const std::exception& ex) {
    if (!tmp.empty()) std::filesystem::remove(tmp);
    throw InputError(platform_label, 0, std::string("cannot load platform: ") + ex.what());
  }
  if (!tmp.empty()) std::filesystem::remove(tmp);
  PlatformModel pm = read_platform(e, platform_label);
  if (is_file && cfg.nodes != pm.nodes && cfg.nodes != 0)
    throw UsageError("--nodes " + std::to_string(cfg.nodes) + " but " + platform_label +
                     " models " + std::to_string(pm.nodes) + " nodes");
  apply_overrides(cfg.overrides, pm, e);
  const int P = pm.nodes;

  std::vector<sg::Host*> hosts;
  for (int r = 0; r < P; ++r)
    hosts.push_back(e.host_by_name(node_host_name(r)));
  hosts.push_back(e.host_by_name(kHostComputerName));
  SimNetwork net(pm.net, pm.topology, P, cfg.fidelity, hosts);
  Delivery delivery(net, cfg.fidelity, hosts);

  std::vector<NodeStats> stats(P + 1);
  if (cfg.timeline)
    for (auto& s : stats)
      s.log = std::make_shared<EventLog>();
  std::vector<std::unique_ptr<SimComm>> comms;
  std::vector<std::unique_ptr<SimContext>> ctxs;
  std::vector<FrameImage> images;
  for (int r = 0; r <= P; ++r) {
    comms.push_back(std::make_unique<SimComm>(r, P, pm.topology, delivery, stats[r]));
    const CostTable cost = r < P ? pm.cost[r] : pm.cost[0];
    const double mem = r < P ? pm.memory[r] : 0.0; // the host computer is not memory-bound
    ctxs.push_back(
        std::make_unique<SimContext>(*comms[r], stats[r], scene, cfg.options, cost, mem, images));
  }

  std::string failure;
  bool oom = false;
  std::vector<char> finished(P + 1, 0);
  auto body = [&](int r, const std::function<void(NodeContext&)>& fn) {
    try {
      fn(*ctxs[r]);
      finished[r] = 1;
    } catch (const OutOfNodeMemory& ex) {
      if (failure.empty()) failure = ex.what();
      oom = true;
      sg::Actor::kill_all();
    } catch (const std::exception& ex) {
      if (failure.empty()) failure = "node " + std::to_string(r) + ": " + ex.what();
      sg::Actor::kill_all();
    }
    stats[r].finish_s = sg::Engine::get_clock();
  };
  for (int r = 0; r < P; ++r)
    sg::Actor::create("node" + std::to_string(r), hosts[r], [&, r] { body(r, algo.node); });
  if (algo.uses_host) sg::Actor::create("srm", hosts[P], [&] { body(P, algo.host); });
  e.run();
  const double vtime = sg::Engine::get_clock();
  // A rank still blocked when nothing else can happen waits for a message nobody sends.
  for (int r = 0; r <= P && failure.empty(); ++r)
    if (!finished[r] && (r < P || algo.uses_host))
      failure = (r < P ? "node " + std::to_string(r) : std::string("host computer")) +
                ": deadlock (still waiting for a message when the simulation ended)";

  SimResult res;
  res.ok = failure.empty();
  res.error = failure;
  nlohmann::json& j = res.report;
  add_run_header(j,
                 {pm.machine, platform_label, topology_name(pm.topology),
                  fidelity_name(cfg.fidelity), preloaded ? scene.path : cfg.scene_path, P},
                 cfg, algo.name, scene);
  j["status"] = res.ok ? "ok" : (oom ? "out_of_memory" : "error");
  if (!res.ok) j["error"] = failure;
  j["virtual_time_s"] = vtime;

  std::vector<NodeRecord> records;
  for (int r = 0; r <= P; ++r) {
    if (r == P && !algo.uses_host) break;
    records.push_back(ctxs[r]->record(r == P ? nlohmann::json("srm") : nlohmann::json(r)));
  }
  add_node_sections(j, records, P, vtime);
  j["model"] = {
      {"startup_short_s", pm.net.startup_short_s},
      {"startup_long_s", pm.net.startup_long_s},
      {"short_max_bytes", pm.net.short_max_bytes},
      {"per_byte_s", pm.net.per_byte_s},
      {"per_hop_s", pm.net.per_hop_s},
      {"switching", pm.net.switching == Switching::Circuit ? "circuit" : "store-and-forward"},
      {"node_memory_bytes", pm.memory.empty() ? 0.0 : pm.memory[0]}};

  add_image_section(j, images, scene, cfg, res.ok, res.images);
  // The seeds' figures this run corresponds to, with the relative error (repro/paper_figures).
  if (auto paper = paper_figures_for(j); !paper.empty()) j["paper"] = paper;
  j["host"] = {{"wall_time_s",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count()},
               {"peak_rss_bytes", peak_rss_bytes()}};
  return res;
}

nlohmann::json run_simulation_isolated(const SimConfig& cfg) {
  return run_batch({cfg}, 1).front();
}

} // namespace zc
