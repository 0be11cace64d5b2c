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
  CostTable cycles;                           // clocks per counted operation (physical estimate)
};

struct OperationMix {
  std::string field; // Counters field
  std::string does;  // what the operation executes
  std::map<std::string, double> mix;
};

// The operation mixes, in Counters field order.
const std::vector<OperationMix>& operation_mixes();
// The plausible range of every operation's cost, as multiples of its physical estimate.
double plausible_low();
double plausible_high();

const std::vector<std::string>& cpu_names();
// The model of a CPU (UsageError for an unknown name).
const CpuModel& cpu_model(const std::string& name);

// Seconds per operation at the CPU's clock, each cost group scaled by scale[g] (cost_groups()
// order; an empty vector means the physical estimate).
CostTable cpu_seconds(const CpuModel& cpu, const std::vector<double>& scale = {});

} // namespace zc
