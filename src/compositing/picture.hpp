#pragma once
// The compositing layer's one shape (in the spirit of IceT's strategies, bswap.c, radixk.c,
// tree.c): a group of nodes, each holding a partial picture of the screen in one representation,
// composites so that each node ends with the final pixels of the rows a region gives it. A
// strategy (binary_swap.cpp, direct_send.cpp, ...) decides who exchanges what with whom; a
// representation (dense.cpp, winning_pixels.cpp, run_length.cpp) decides how rows travel, what
// the modelled machine is charged for them and how they merge. docs/compositing.md.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "comm/comm.hpp"
#include "raster/active_pixels.hpp"
#include "util/counters.hpp"

namespace zc::compositing {

// The node's modelled memory (the caller adapts its own: NodeContext::alloc and release).
class Memory {
public:
  virtual ~Memory() = default;
  virtual void alloc(double bytes, const std::string& what) = 0; // may throw (out of memory)
  virtual void release(double bytes) = 0;
};

// What a strategy sees of a node: the group's Comm (group ranks 0..size-1, group.hpp), its
// memory, and the operations it counts. Without charge_round the caller charges them when its
// phase ends (Kurc et al.'s programs, as calibrated); with it, after each round's merge, before the
// node sends again (Blazek's merge: a node forwards its buffer once it has merged).
struct Node {
  Comm& comm;
  Memory& memory;
  Counters& work;
  std::function<void(const Counters&)> charge_round = {};
};
// A round's merge is done: its work charged now when the node charges by round.
inline void end_round(Node& n) {
  if (!n.charge_round || n.work == Counters{}) return;
  n.charge_round(n.work);
  n.work = Counters{};
}

// What compositing measured on a node: the bytes it was charged for at each communication step
// (Kurc et al.'s Fig. 1) and its merge load (the pixels or locations it merged: Fig. 2).
struct Measures {
  std::vector<double> step_bytes;
  std::uint64_t merge_load = 0;
};

// How the pixels received are merged: two x-sorted lists into a new list (Kurc et al. §3.1, a
// pairwise exchange), or every message z-buffered into the rows kept (§3.2). A dense picture
// merges location by location either way.
enum class Merge { Lists, Zbuffer };

// Where the rows go at one exchange: dest[y] is the group rank that row y's pixels go to next
// (self: kept; -1: nowhere), for every row of the screen. A picture sends only the rows it still
// holds. `incoming` messages will arrive, each over the rows this node keeps (every strategy
// exchanges among nodes that hold the same rows).
struct Routing {
  const std::vector<int>& dest;
  int self = 0;
  int parts = 0; // the group's size: dest values are below it
  int incoming = 0;
};

// A node's partial picture in one representation.
class Picture {
public:
  virtual ~Picture() = default;
  virtual const char* representation() const = 0;
  // The messages to every group rank (out[self] empty) holding the rows routed to it, charged as
  // the model's records; packing counted into n.work and the buffers held allocated.
  virtual std::vector<Message> split(const Routing& r, Merge how, Node& n) = 0;
  // Merges the messages that arrived (in their senders' group-rank order) into the rows kept at
  // the last split; returns the pixels or locations merged.
  virtual std::uint64_t merge(std::vector<Message> in, Merge how, Node& n) = 0;
  // The covered pixels of the rows the node holds at the end (taken once, for the output); the
  // work of making them pixel records counted into w.
  virtual ActivePixels final_pixels(Counters& w) = 0;
};

} // namespace zc::compositing
