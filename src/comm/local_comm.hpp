#pragma once
// An in-process Comm: every rank a thread of this process, each message handed to its receiver's
// mailbox at once (a buffered send: isend's handle is complete when it returns). It keeps the
// interface's matching rules, by source and tag with any-source receives, one stream per source
// and tag in send order, and the host computer as rank size(), and models no time: now() is the
// host's clock since the run began. It runs the collectives' and the compositing strategies' data
// paths in unit tests without SimGrid; the simulator (src/sim) stays the one that times them.
#include <functional>

#include "comm/comm.hpp"

namespace zc {

struct LocalRun {
  bool host = false; // also run rank_main as the host computer (rank `nodes`)
  // A receive that waits this long fails the run (a deadlock is an error, not a hang).
  double deadlock_after_s = 30;
};

// Runs rank_main(comm) on every rank 0..nodes-1 (and the host when asked), each on its own
// thread, and returns when all have. The first exception a rank throws is rethrown here; the ranks
// still waiting for a message are woken and fail instead of waiting for it forever.
void run_local(int nodes, Topology topology, const std::function<void(Comm&)>& rank_main,
               LocalRun options = {});

} // namespace zc
