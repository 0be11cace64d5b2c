#pragma once
// A message on its way through the simulated machine: the payload (or the blocks) it shares with
// its sender, the size it is charged, and when it is fully received.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "comm/comm.hpp"
#include "sim/sim_network.hpp"

namespace zc {

constexpr double kNotYet = std::numeric_limits<double>::infinity();

struct Transit {
  int src, dst, tag;
  Payload data;
  Blocks blocks;       // a message of several blocks (Comm::isend_blocks), their payloads shared
  bool bundle = false; // whether it is one
  std::size_t charged = 0; // the bytes the network is charged (comm.hpp)
  double sent_at = 0;
  double arrival = kNotYet; // virtual time of full reception, kNotYet while contention decides it
  // Progress through the circuit fidelity's holds (Delivery's channel bookkeeping).
  std::vector<Hold> holds;
  std::size_t stage = 0, next_channel = 0;
  std::uint32_t owners = 0; // TransitPtrs to it
};

// Shared ownership of a Transit, as std::shared_ptr but without its allocation and atomic counts:
// a simulation runs on one thread, and a message is made and dropped for every send. The last
// owner hands the Transit back to its thread's free list, which keeps its holds' vectors for the
// next message (no allocation a message once a run is under way).
class TransitPtr {
public:
  TransitPtr() = default;
  TransitPtr(std::nullptr_t) {} // NOLINT(google-explicit-constructor): as a shared_ptr
  TransitPtr(const TransitPtr& o) : t_(o.t_) {
    if (t_) ++t_->owners;
  }
  TransitPtr(TransitPtr&& o) noexcept : t_(std::exchange(o.t_, nullptr)) {}
  TransitPtr& operator=(TransitPtr o) noexcept {
    std::swap(t_, o.t_);
    return *this;
  }
  ~TransitPtr() { reset(); }

  // A Transit of this thread's free list (or a new one), its fields as a new Transit's but for
  // the holds' capacity.
  static TransitPtr make();

  void reset() {
    if (t_ && --t_->owners == 0) recycle(t_);
    t_ = nullptr;
  }
  Transit* get() const { return t_; }
  Transit* operator->() const { return t_; }
  Transit& operator*() const { return *t_; }
  explicit operator bool() const { return t_ != nullptr; }
  friend bool operator==(const TransitPtr& a, const TransitPtr& b) { return a.t_ == b.t_; }

private:
  static void recycle(Transit* t);
  Transit* t_ = nullptr;
};

} // namespace zc
