#include "mpi/probe.hpp"

#include <mpi.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <set>

#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "mpi/mpi_session.hpp"
#include "mpi/probe_cpu.hpp"
#include "mpi/probe_net.hpp"
#include "util/error.hpp"

namespace zc {

std::vector<std::string> probe_outputs(const ProbeOptions& o, int ranks) {
  if (o.nodes.size() <= 1) return {o.out};
  std::string stem = o.out, ext = ".xml";
  if (stem.ends_with(".xml")) stem.resize(stem.size() - 4);
  std::vector<std::string> v;
  for (int p : o.nodes)
    v.push_back(stem + "-" + std::to_string(p) + ext);
  (void)ranks;
  return v;
}

namespace {

nlohmann::json cost_json(CostTable t) {
  nlohmann::json c = nlohmann::json::object();
  for (auto& [id, v] : t.fields())
    c[id] = *v;
  return c;
}

// A barrier whose waiting ranks sleep instead of polling (MPI_Barrier spins): while rank 0 times
// its loops alone, the other cores stay idle.
void sleeping_barrier() {
  MPI_Request r = MPI_REQUEST_NULL;
  MPI_Ibarrier(MPI_COMM_WORLD, &r);
  for (int done = 0;;) {
    MPI_Test(&r, &done, MPI_STATUS_IGNORE);
    if (done) return;
    const timespec ms{0, 1000000};
    nanosleep(&ms, nullptr);
  }
}

// How the probe's ranks time the CPU together (measure_cpu): rank 0 alone while the others sleep
// (what a one-node run has: the other cores idle), then every rank at once (a run on several
// nodes: every core busy, sharing the memory system and the last-level cache).
ProbeRanks mpi_probe_ranks(int rank) {
  ProbeRanks ranks;
  ranks.times_alone = rank == 0;
  ranks.wait = sleeping_barrier;
  ranks.share = [](const std::vector<double>& mine) {
    std::vector<double> k = mine;
    std::uint64_t groups = k.size();
    MPI_Bcast(&groups, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    k.resize(std::size_t(groups));
    MPI_Bcast(k.data(), int(groups), MPI_DOUBLE, 0, MPI_COMM_WORLD);
    return k;
  };
  return ranks;
}

// What every rank reported, at rank 0: their tables averaged field by field, the ranks on each
// host, the memory a node gets (the smallest host's share), every rank's report.
struct RankReports {
  CostTable avg;
  std::map<std::string, int> ranks_on;
  double memory = 1e300;
  nlohmann::json per_rank = nlohmann::json::array();
};
RankReports merge_reports(const std::vector<Bytes>& all) {
  RankReports r;
  for (auto& [id, v] : r.avg.fields())
    *v = 0;
  std::map<std::string, double> mem_of;
  for (const auto& b : all) {
    const auto j = nlohmann::json::parse(std::string(b.begin(), b.end()));
    for (auto& [id, v] : r.avg.fields())
      *v += j["cost"][id].get<double>() / double(all.size());
    ++r.ranks_on[j["host"]];
    mem_of[j["host"]] = j["memory"];
    r.per_rank.push_back(j);
  }
  for (const auto& [h, n] : r.ranks_on)
    r.memory = std::min(r.memory, mem_of[h] / n);
  return r;
}

// The cluster as a machine: the iPSC/860's description with the measured network and memory.
MachineSpec cluster_spec(const RankReports& r, const NetFit& net, int size) {
  MachineSpec spec = machine_spec("ipsc860");
  spec.name = "cluster";
  std::string hosts;
  for (const auto& [h, n] : r.ranks_on)
    hosts += (hosts.empty() ? "" : ", ") + h + " x" + std::to_string(n);
  spec.description = "a cluster measured on " + hosts;
  spec.generated_by = "`mpirun -np " + std::to_string(size) + " zcube probe`";
  spec.memory_bytes = std::floor(r.memory);
  // A message costs at least its envelope at the measured rate (a fit on a fast, noisy cluster can
  // come out below it, which no platform can express).
  const double envelope_s = kSmpiEnvelopeBytes * net.per_byte_s;
  spec.net.startup_short_s = std::max(net.short_s, envelope_s);
  spec.net.startup_long_s = std::max(net.long_s, envelope_s);
  spec.net.short_max_bytes = net.short_max_bytes;
  spec.net.per_byte_s = net.per_byte_s;
  spec.net.per_hop_s = 0;
  // Two messages crossing share the memory system: each direction's per-byte cost while the other
  // is busy too is 2 / both_ways_Bps (a duplex limit, as the Volvox's T800 links have); none when
  // the exchange is no slower a byte than one message alone.
  spec.net.both_ways_Bps =
      net.both_busy_per_byte_s > net.per_byte_s ? 2.0 / net.both_busy_per_byte_s : 0.0;
  spec.net.switching = Switching::Circuit;
  // The cluster's programs are zcube's: its messages move zcube's payloads (13 bytes a winning
  // pixel, 11 a z-buffer location), not the papers' records (9, 7).
  spec.net.charge_payloads = true;
  spec.net.host_startup_s = net.short_s;
  spec.net.host_per_byte_s = net.per_byte_s;
  spec.cost_calibrated = true;
  return spec;
}

// A platform file a node count asked for; returns what was written.
nlohmann::json write_platforms(const ProbeOptions& o, MachineSpec spec, const CostTable& solo,
                               const CostTable& avg, int size) {
  const auto outs = probe_outputs(o, size);
  std::vector<int> counts = o.nodes.empty() ? std::vector<int>{size} : o.nodes;
  nlohmann::json written = nlohmann::json::array();
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const int P = counts[i];
    // A power of two is a hypercube (per-hop cost 0, so only contention differs), else a ring.
    const Topology topo = (P & (P - 1)) == 0 ? Topology::Cube : Topology::Ring;
    // One node computes alone; several share the machine's cores, memory and cache as the ranks
    // did that timed their loops at once (more nodes than ranks: as many cores busy as ranks).
    spec.cost = P == 1 ? solo : avg;
    std::ofstream f(outs[i]);
    f << platform_xml(spec, P, topo);
    if (!f) throw InputError(outs[i], 0, "cannot write the platform file");
    written.push_back({{"file", outs[i]}, {"nodes", P}, {"topology", topology_name(topo)}});
  }
  return written;
}

nlohmann::json network_json(const NetFit& net, double both_ways_Bps) {
  return {{"startup_short_s", net.short_s},
          {"startup_long_s", net.long_s},
          {"short_max_bytes", net.short_max_bytes},
          {"per_byte_s", net.per_byte_s},
          {"both_busy_fit_s", net.both_busy_fit_s},
          {"both_busy_per_byte_s", net.both_busy_per_byte_s},
          {"both_ways_Bps", both_ways_Bps},
          {"exchanges", net.exchanges},
          {"ranges", net.ranges},
          {"samples", net.samples}};
}

} // namespace

nlohmann::json probe_cluster(const ProbeOptions& o) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size < 2)
    throw UsageError("probe measures the network between MPI processes: mpirun -np P zcube probe "
                     "(P >= 2)");
  for (int p : o.nodes)
    if (p < 1) throw UsageError("probe --nodes: node counts must be positive");
  const NetFit net = measure_network(rank, size);
  const CpuProbe cpu = measure_cpu(o.root, o.seconds, mpi_probe_ranks(rank));
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  const nlohmann::json mine = {{"host", processor_name()},
                               {"cost", cost_json(cpu.at_once.cost)},
                               {"cpu", cpu.at_once_log},
                               {"memory", double(pages) * double(page)}};
  const std::string text = mine.dump();
  const auto all = gather_to_root(Bytes(text.begin(), text.end()));
  if (rank != 0) return nlohmann::json::object();
  const RankReports reports = merge_reports(all);
  const MachineSpec spec = cluster_spec(reports, net, size);
  const nlohmann::json written = write_platforms(o, spec, cpu.alone.cost, reports.avg, size);
  return {{"network", network_json(net, spec.net.both_ways_Bps)},
          {"cost", cost_json(reports.avg)},
          {"cost_alone", cost_json(cpu.alone.cost)},
          {"cpu_alone", cpu.alone_log},
          {"ranks", reports.per_rank},
          {"memory_bytes_per_node", spec.memory_bytes},
          {"platforms", written},
          {"ranks_measured", size}};
}

} // namespace zc
