#pragma once
// Machine models as data: the network's message-cost formula, node memory, and the CPU cost
// table (seconds per counted renderer operation). The built-in figures come from
// docs/machines.md (sources and confidence there); a platform XML carries the same numbers
// as properties, and a simulation reads them back from the XML, so a what-if study edits data.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "machine/topology.hpp"
#include "util/counters.hpp"

namespace zc {

// Seconds per counted operation, one entry per Counters field (ZC_COUNTER_FIELDS order).
// The largest node memory zcube models: a node's byte counts are doubles, exact up to 2^53; 1 PiB
// keeps every sum of them well inside.
constexpr double kMaxNodeMemory_bytes = 1125899906842624.0; // 2^50

struct CostTable {
#define ZC_COST_FIELD(f) double f = 0;
  ZC_COUNTER_FIELDS(ZC_COST_FIELD)
#undef ZC_COST_FIELD
  // Virtual seconds the operations `c` take: sum of count x cost.
  double seconds(const Counters& c) const;
  CostTable scaled(double k) const;
  // (property name "cost_<field>", value) pairs in field order.
  std::vector<std::pair<std::string, double*>> fields();
};

enum class Switching { Circuit, StoreAndForward };

// One message of m bytes over h hops, without contention and with the reverse directions idle:
//   circuit (DCM):        startup(m) + m*per_byte + (h-1)*per_hop
//   store-and-forward:    h * (startup(m) + m*per_byte)
// startup(m) = startup_short for m <= short_max_bytes, startup_long above (two protocols).
struct NetworkParams {
  double startup_short_s = 0;
  double startup_long_s = 0;
  double short_max_bytes = 100;
  double per_byte_s = 0;
  double per_hop_s = 0;
  Switching switching = Switching::Circuit;
  double host_startup_s = 0; // host (SRM) link to node 0
  double host_per_byte_s = 0;
  // Bytes a second a node-to-node link carries in all while both its directions carry data; 0: full
  // duplex, each direction at 1/per_byte_s whatever the other does (the DCM). A T800 link carries
  // 1.7 MB/s one way but 2.35 MB/s in all both ways (docs/machines.md): each direction then moves
  // half of it.
  double both_ways_Bps = 0;
  // What a message is charged: the modelled program's records (Message::charged, the papers'
  // record sizes: false), or the bytes zcube's own payloads hold (true), for a machine whose
  // programs are zcube's (a cluster `zcube probe` measured: its MPI backend moves the payloads).
  bool charge_payloads = false;

  // True when a direction slows down while the other direction of its link also carries data.
  bool half_duplex_limited() const {
    return both_ways_Bps > 0 && per_byte_s > 0 && both_ways_Bps * per_byte_s < 2.0;
  }
  // Seconds a byte takes in one direction while the other direction is busy too.
  double both_busy_per_byte_s() const { return 2.0 / both_ways_Bps; }

  double startup(double bytes) const {
    return bytes <= short_max_bytes ? startup_short_s : startup_long_s;
  }
  double message_time(double bytes, int hops) const;
  double host_link_time(double bytes) const { return host_startup_s + bytes * host_per_byte_s; }
};

struct MachineSpec {
  std::string name;        // ipsc2, ipsc860, volvox
  std::string description; // one line for the XML and the README
  double memory_bytes = 0; // per node
  // Memory the node's operating system keeps resident (kernel, message buffer pool, the program's
  // own code and stack), charged on every node before the algorithm's first buffer: NX/2 on the
  // iPSC/2, NX on the iPSC/860 (docs/memory.md: derivation and range).
  double os_resident_bytes = 0;
  NetworkParams net;
  std::string cpu; // the CPU model (machine/cpu_model.hpp) its cost table comes from
  CostTable cost;  // seconds per counted operation
  bool cost_calibrated = false;
  std::string generated_by; // the platform file's provenance line; empty: `zcube platform ...`
};

// Counters fields whose costs scale by one multiplier: the same kind of work (geometry per
// triangle or vertex, per span or row, per pixel, ...).
struct CounterGroup {
  std::string name;
  std::vector<std::string> fields; // Counters field names
};
// The cost groups: the calibration fits one multiplier per group, the calibrated tables and the
// uncertainty analysis scale them (the MPI probe prices finer groups: mpi/probe_groups.hpp).
const std::vector<CounterGroup>& cost_groups();
// Multiplies every field of group g by scale[g] (the cost groups, or others).
CostTable scale_groups(const CostTable& t, const std::vector<double>& scale);
CostTable scale_groups(const CostTable& t, const std::vector<CounterGroup>& groups,
                       const std::vector<double>& scale);
// Seconds the operations of `work` take at `prices`, one figure per group (the columns of the
// calibration's and the probe's linear fits).
std::vector<double> group_seconds(const CostTable& prices, const std::vector<CounterGroup>& groups,
                                  const Counters& work);
// The physical estimate of the iPSC/2's 80386 + 80387 table (machine/cpu_model.hpp), the point the
// calibration starts from and is bounded around.
CostTable prior_i386_costs();
// The calibrated tables: the physical estimates of the 80386 (iPSC/2) and of the i860 XR (iPSC/860,
// Volvox), each cost group scaled by the multipliers fitted on the iPSC/2 (calibrated_costs.hpp).
std::vector<double> calibrated_group_scale();
CostTable i386_costs();
CostTable i860_costs();

const std::vector<std::string>& machine_names();
// The built-in model of a machine; UsageError for an unknown name.
const MachineSpec& machine_spec(const std::string& name);

// Whether `machine` (a --machine argument) names a platform file rather than a built-in machine.
inline bool is_platform_file(const std::string& machine) {
  return machine.size() > 4 && machine.ends_with(".xml");
}

} // namespace zc
