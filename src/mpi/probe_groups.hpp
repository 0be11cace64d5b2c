#pragma once
// The probe's cost groups and its blocks of loops, in the order they are measured and solved
// (probe_cpu.hpp), and the table the groups' multipliers scale.
#include <cstddef>
#include <vector>

#include "machine/machine.hpp"

namespace zc::cpu_probe {

// The probe's cost groups, in the order they are measured: one multiplier each on the prior table
// (the 80386's physical estimate keeps the proportions inside a group). Each block of loops below
// measures its own groups with every group measured before it subtracted at the cost found.
enum Group : std::size_t {
  kVertex,
  kTriangle,
  kEstimate,
  kTessellate,
  kClear,
  kPacking,
  kMerge,
  kListMerge,
  kRecords,
  kTriangleRecords,
  kEdges,
  kSpans,
  kPixels,
  kFarLines,
  kDistantLines,
  kSort,
  kWpaTested,
  kWpaAppended,
  kRecordFetches,
  kScan,
  kWire,
  kGroups
};

const std::vector<CostGroup>& probe_groups();

// The blocks of loops, in the order they are solved (loop_blocks()).
enum LoopBlockId : std::size_t {
  kProjectLoops,
  kSetupLoops,
  kEstimateLoops,
  kTessellateLoops,
  kClearLoops,
  kPackingLoops,
  kMergeLoops,
  kListMergeLoops,
  kWireLoops,
  kOutputLoops,
  kDenseOutputLoops,
  kMultiScatterLoops,
  kNearZbufferLoops,
  kZbufferLoops,
  kSpanListLoops,
  kActiveLoops,
};

// A block of loops: the groups its loops measure, solved together (most blocks have one).
struct LoopBlock {
  const char* name;
  std::vector<std::size_t> groups;
};
const std::vector<LoopBlock>& loop_blocks();

// The table the probe's multipliers scale (probe_groups.cpp says what it holds).
CostTable probe_prior();

} // namespace zc::cpu_probe
