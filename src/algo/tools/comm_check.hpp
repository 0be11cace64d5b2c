#pragma once
#include "algo/algorithm.hpp"

namespace zc {
// Self-test of a backend's communication layer: every collective of comm/collectives (broadcast,
// scatter, gather, reduce from several roots; all-gather, all-reduce, prefix sum, both all-to-all
// schedules, barrier), point-to-point FIFO order per (source, tag) and crossing blocking sends of
// 1 MiB (a send never waits for its receiver), each checked against the
// data it must deliver. The run fails (status error, naming the wrong operations) when any is
// wrong; node metrics "comm_check_failures" list them. The same code runs on SimGrid and on MPI.
Algorithm comm_check_algorithm();
} // namespace zc
