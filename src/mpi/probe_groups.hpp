#pragma once
// The probe's groups of counters and its blocks of loops, in the order they are measured and solved
// (probe_cpu.hpp), and the table the groups' multipliers scale.
#include <cstddef>
#include <vector>

#include "machine/machine.hpp"

namespace zc::cpu_probe {

// The probe's groups (probe groups), in the order they are measured: one multiplier each on the
// prior table (the 80386's physical estimate keeps the proportions inside a group). Each block of
// loops below measures its own groups with every group measured before it subtracted at the cost
// found. They are not the calibration's eight cost groups (machine.hpp cost_groups()), fitted to
// the papers' published times: the probe times zcube's own loops, each kind of work apart, and so
// prices finer groups. A probe group named as a cost group ("spans", "pixels", "clear", "merge",
// "packing", "list_merge") holds some or all of that cost group's counters: the probe's "spans"
// holds spans and span starts, the cost group also the edges, sort steps and record fetches (probe
// groups of their own) and the rows scanned (the probe's "estimate"). The names are the probe's
// output (probe.json), so they stay.
enum ProbeGroup : std::size_t {
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
  kProbeGroups
};

const std::vector<CounterGroup>& probe_groups();

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

// A block of loops: the probe groups its loops measure, solved together (most blocks have one).
struct LoopBlock {
  const char* name;
  std::vector<std::size_t> groups;
};
const std::vector<LoopBlock>& loop_blocks();

// The table the probe's multipliers scale (probe_groups.cpp says what it holds).
CostTable probe_prior();

} // namespace zc::cpu_probe
