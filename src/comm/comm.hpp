#pragma once
// The communication layer, in the spirit of PPCM (Charles et al. §3): a topology-aware
// point-to-point interface on which the collectives are written once for every backend. It holds
// no SimGrid type: the SimGrid backend (src/sim) implements it, and the MPI backend (src/mpi).
//
// Payloads are the real data. What the network is charged is a message's `charged` size: by
// default the payload's size, or the size of the records the modelled machine's program holds and
// sends (docs/papers.md, "Records"), when zcube's payload carries bytes that program never sent
// (a triangle id for the depth tie-break, clip-space floats). The charged size travels with the
// message, so a collective that forwards it charges what it received.
//
// A payload is immutable once made and shared, not copied, between the nodes a message reaches
// (payload.hpp): copying a Message copies a reference.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "comm/payload.hpp"
#include "machine/topology.hpp"

namespace zc {

// A payload and the bytes the modelled machine is charged for it.
struct Message {
  Payload payload;
  std::size_t charged = 0;
};
// A message charged as its payload's size: the default, where zcube sends the bytes the modelled
// program sent.
inline Message charged_as_payload(Payload payload) {
  const std::size_t n = payload.size();
  return {std::move(payload), n};
}

// One node's block inside a message that carries several (the collectives' forwarding).
struct Block {
  int owner;
  Message data;
};
using Blocks = std::vector<Block>;
// Such a message is charged the blocks' charged sizes plus the framing the modelled program sends:
// a count (4 bytes), and an owner and a length a block (12 bytes each).
constexpr std::size_t kBlocksFrameBytes = 4, kBlockFrameBytes = 12;
std::size_t blocks_charged(const Blocks& blocks);
// The same of `count` blocks whose charged sizes add up to `charged` (a replay's, sim/replay).
std::size_t blocks_charged(std::size_t count, std::size_t charged);
// The blocks as one payload (u32 count; per block i32 owner, u64 size, u64 charged; the data),
// for a backend that sends bytes, and back. The payload size is what a report counts as sent.
Message pack_blocks(const Blocks& blocks);
Blocks unpack_blocks(const Message& m);
std::size_t packed_blocks_size(const Blocks& blocks);
// The same of `count` blocks of `payload_bytes` in all.
std::size_t packed_blocks_size(std::size_t count, std::size_t payload_bytes);

constexpr int kAnySource = -1;

// Completion of an asynchronous send.
class SendRequest {
public:
  virtual ~SendRequest() = default;
  virtual void wait() = 0;
};
using SendHandle = std::unique_ptr<SendRequest>;

class Comm {
public:
  virtual ~Comm() = default;

  virtual int rank() const = 0; // 0..size()-1 for nodes; size() for the host computer
  virtual int size() const = 0; // number of nodes (the host is not counted)
  virtual Topology topology() const = 0;
  int host_rank() const { return size(); }
  bool is_host() const { return rank() == size(); }
  int dimension() const { return topology() == Topology::Cube ? log2_exact(size()) : 0; }
  int neighbour(int channel) const { return zc::neighbour(topology(), size(), rank(), channel); }

  // Asynchronous send: the transfer proceeds while the caller continues; wait() on the handle.
  virtual SendHandle isend(int dst, int tag, Message m) = 0;
  // Blocking receive of the next message from src (or kAnySource) with this tag. Messages from one
  // source with one tag arrive in the order they were sent. `from` receives the actual source.
  virtual Message recv_message(int src, int tag, int* from = nullptr) = 0;

  SendHandle isend(int dst, int tag, Bytes data) {
    return isend(dst, tag, charged_as_payload(std::move(data)));
  }
  // Several blocks as one message (charged as blocks_charged says), received whole by
  // recv_blocks. By default packed into one payload; the simulator passes the blocks' shared
  // payloads on as they are, so a collective forwards what it received without copying it.
  virtual SendHandle isend_blocks(int dst, int tag, Blocks blocks) {
    return isend(dst, tag, pack_blocks(blocks));
  }
  virtual void send_blocks(int dst, int tag, Blocks blocks) { send(dst, tag, pack_blocks(blocks)); }
  virtual Blocks recv_blocks(int src, int tag, int* from = nullptr) {
    return unpack_blocks(recv_message(src, tag, from));
  }
  // Blocking send: returns when the message has been delivered.
  virtual void send(int dst, int tag, Message m) { isend(dst, tag, std::move(m))->wait(); }
  void send(int dst, int tag, Bytes data) { send(dst, tag, charged_as_payload(std::move(data))); }
  Bytes recv(int src, int tag, int* from = nullptr) {
    return std::move(recv_message(src, tag, from).payload).take();
  }

  // Virtual (or, for a real backend, wall-clock) time in seconds.
  virtual double now() const = 0;
};

} // namespace zc
