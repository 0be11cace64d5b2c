#pragma once
// The heap mapped before anything is timed: the probe (probe_cpu, probe_net) and the MPI runs.
#include <cstddef>

namespace zc {

// Maps and touches `bytes` of heap before anything is timed and keeps them (every allocation from
// the heap, none given back): the probe's loops and the MPI runs then find their buffers in memory
// that is already there, as a 1990 node's physical memory was, instead of paying the host's demand
// paging (a page fault and a zeroed page at a buffer's first touch) in whichever loop touches a
// fresh buffer first. The probe and the MPI runs both call it.
void premap_heap(std::size_t bytes);

} // namespace zc
