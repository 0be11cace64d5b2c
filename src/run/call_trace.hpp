#pragma once
// Record and replay (docs/simulator.md, "Record and replay"): the calls each node program makes
// on its NodeContext and Comm during one run, in order. A node program sees the machine only
// through those two interfaces and never reads the clock (except pingpong, through Comm::now), so
// its calls depend on the scene, the algorithm and its options, the node count and the topology,
// and on which source a receive from any source got: not on the CPU costs, the network or the
// fidelity. Replaying the calls under other costs (sim/replay.hpp) gives the report a full run
// would give, without rendering or the messages' contents.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run/image_check.hpp"

#include "algo/algorithm.hpp"
#include "machine/topology.hpp"
#include "util/counters.hpp"

namespace zc {

enum class CallKind : std::uint8_t {
  Charge,      // counters[index]
  PhaseBegin,  // strings[index]
  PhaseEnd,    //
  TimedStart,  //
  TimedEnd,    //
  Alloc,       // bytes, strings[index] (what)
  Release,     // bytes
  Isend,       // peer (dst), tag, size (payload bytes), charged; handle
  IsendBlocks, // peer, tag, blocks[index]; handle
  Send,        // peer, tag, size, charged (blocking)
  SendBlocks,  // peer, tag, blocks[index] (blocking)
  Wait,        // handle
  Drop,        // handle (the send's handle destroyed)
  Recv,        // peer (the source asked, or kAnySource), tag; from (the source it got)
  Metrics,     // the node's metrics became metrics[index]
};

struct Call {
  CallKind kind = CallKind::Charge;
  std::int32_t peer = 0, tag = 0, from = 0;
  std::uint32_t index = 0, handle = 0;
  std::uint64_t size = 0, charged = 0;
  double bytes = 0;
};

// One block of a message of blocks: its owner, payload and charged bytes.
struct TracedBlock {
  std::int32_t owner = 0;
  std::uint64_t size = 0, charged = 0;
};

struct CallTrace {
  int nodes = 0;
  Topology topology = Topology::Cube;
  std::vector<std::vector<Call>> ranks; // the P nodes, then the host computer (when it ran)
  std::vector<Counters> counters;
  std::vector<std::string> strings;
  std::vector<std::vector<TracedBlock>> blocks;
  std::vector<std::string> metrics; // JSON text
  bool read_clock = false;          // a node read Comm::now: its calls may depend on the times
  ImageVerdict image;               // the recorded run's pictures, checked
  std::map<std::string, std::uint32_t> string_ids; // while recording

  std::uint32_t string_id(const std::string& s);
  std::vector<std::uint8_t> serialize() const;
  static CallTrace parse(const std::vector<std::uint8_t>& bytes);
};

// `a` with its node (and host) program's calls recorded into `trace` as the run goes.
Algorithm recording_algorithm(const Algorithm& a, std::shared_ptr<CallTrace> trace);

} // namespace zc
