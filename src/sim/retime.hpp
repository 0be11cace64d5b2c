#pragma once
// Retiming a recorded run under other machine figures, in this process and without SimGrid
// (docs/uncertainty.md, "How a draw is priced"). A run's calls (run/call_trace.hpp) do not depend
// on the machine's figures, so the times of one draw of the uncertainty model follow from the
// calls alone: each rank's charges priced by the draw's cost table, its messages by the draw's
// network, under the same rules the simulator's Delivery applies (a receive waits for its
// message's arrival, a send's handle for its message; circuit switching's channels granted first
// come, first served; ranks due at one time in rank order, the network after them). Every draw is
// a discrete-event simulation of its own, so contention is decided anew under each draw.
//
// It covers the analytic and circuit fidelities on links whose directions do not slow each other
// down; the flow fidelity (SimGrid's bandwidth sharing) and the Volvox's T800 links are left to
// full simulations (retimable() says why). A receive from any source that would get another source
// under a draw than the recorded one keeps the recorded source, and the draw counts it: that
// draw's calls could have differed, so its times are an approximation the report owns up to.
#include <string>
#include <vector>

#include "machine/machine.hpp"
#include "machine/uncertainty.hpp"
#include "run/call_trace.hpp"
#include "run/fidelity.hpp"

namespace zc {

// The machine a trace was recorded on, after its what-ifs (sim/platform_load's PlatformModel).
struct RetimeMachine {
  int nodes = 0;
  Topology topology = Topology::Cube;
  Fidelity fidelity = Fidelity::Circuit;
  NetworkParams net;
  std::vector<CostTable> cost; // per node; the host computer is priced as node 0
  std::vector<double> memory;  // per node
  double os_resident = 0;
  double precision = 1e-12; // SimGrid's surf/precision of the run
};

// The figures of one retimed draw, as the report states them.
struct RetimedRun {
  enum class Status { Ok, OutOfMemory, Diverged } status = Status::Ok;
  std::string why;
  // Receives from any source that found another sender's message first under this draw and were
  // kept in the recorded order (the program's later calls could have differed).
  int reordered_receives = 0;
  double virtual_time_s = 0;
  double timed_s = -1;                  // -1: no node marked a timed region
  std::vector<std::string> phase_names; // in first-entered order over the ranks
  std::vector<double> phase_max_s;      // the critical node's total, per phase
};

// Whether retime() reproduces the simulator on this machine ("" if so, else why not); the first
// form from what a configuration says before it runs.
std::string retimable(Fidelity fidelity, const NetworkParams& net);
std::string retimable(const RetimeMachine& m);

// The run `trace` under `draw` (ModelDraw{} is the nominal machine).
RetimedRun retime(const CallTrace& trace, const RetimeMachine& m, const ModelDraw& draw);

} // namespace zc
