#pragma once
// The communication layer, in the spirit of PPCM (Charles et al. §3): a topology-aware
// point-to-point interface on which the collectives are written once for every backend. It holds
// no SimGrid type: the SimGrid backend (src/sim) implements it now, an MPI backend can later.
// Payloads are the real data; their size is what the network is charged.
#include <cstdint>
#include <memory>
#include <vector>

#include "machine/topology.hpp"

namespace zc {

using Bytes = std::vector<std::uint8_t>;

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

  // Blocking send: returns when the message has been delivered.
  virtual void send(int dst, int tag, Bytes data) = 0;
  // Asynchronous send: the transfer proceeds while the caller continues; wait() on the handle.
  virtual SendHandle isend(int dst, int tag, Bytes data) = 0;
  // Blocking receive of the next message from src (or kAnySource) with this tag. Messages from one
  // source with one tag arrive in the order they were sent. `from` receives the actual source.
  virtual Bytes recv(int src, int tag, int* from = nullptr) = 0;

  // Virtual (or, for a real backend, wall-clock) time in seconds.
  virtual double now() const = 0;
};

} // namespace zc
