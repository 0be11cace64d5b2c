#pragma once
// CPU cost models from first principles, as data (machines/cpu/*.json, compiled in): each counted
// renderer operation is an instruction mix (operations.json: what compiled C of the period
// executes for it), each CPU gives the clocks of every instruction class with its source
// (i80386.json for the iPSC/2's 80386 + 80387, i860xr.json for the i860 XR of the iPSC/860 and the
// Volvox). An operation's physical estimate is sum(count x clocks) / clock rate; the calibration
// may scale a cost group only within the operations' plausible range (docs/machines.md).
#include <map>
#include <string>
#include <vector>

#include "machine/machine.hpp"

namespace zc {

struct InstructionClass {
  double cycles = 0;
  std::string why, source;
};

struct CpuModel {
  std::string name;        // i80386, i860xr
  std::string description; // one line
  double clock_hz = 0;
  std::map<std::string, InstructionClass> classes;
  std::map<std::string, std::string> sources; // key -> full reference
  CostTable cycles; // clocks per counted operation of the modelled programs (physical estimate)
  CostTable zcube_cycles; // clocks of zcube's own loop for every operation, zcube-only ones too
};

struct OperationMix {
  std::string field; // Counters field
  std::string does;  // what the operation executes
  std::map<std::string, double> mix;
  // zcube's own work for its messages, which the papers' programs do not do: the CPU's table
  // prices it 0 (CpuModel::cycles), its mix is the probe's reference (zcube_loop_seconds).
  bool zcube_only = false;
};

// The operation mixes, in Counters field order.
const std::vector<OperationMix>& operation_mixes();
// The plausible range of every operation's cost, as multiples of its physical estimate.
double plausible_low();
double plausible_high();

const std::vector<std::string>& cpu_names();
// The model of a CPU (UsageError for an unknown name).
const CpuModel& cpu_model(const std::string& name);

// Seconds per operation of zcube's own loops at the CPU's clock (zcube-only operations included):
// the reference the probe scales to this machine's costs.
CostTable zcube_loop_seconds(const CpuModel& cpu);

// Seconds per operation at the CPU's clock, each cost group scaled by scale[g] (cost_groups()
// order; an empty vector means the physical estimate).
CostTable cpu_seconds(const CpuModel& cpu, const std::vector<double>& scale = {});

} // namespace zc
