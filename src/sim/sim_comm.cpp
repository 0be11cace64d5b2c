#include "sim/sim_comm.hpp"

#include <stdexcept>

#include "sim/free_list.hpp"

namespace zc {

namespace sg = simgrid::s4u;

namespace {
struct OperatorDelete {
  void operator()(void* p) const { ::operator delete(p); }
};

class SimSendRequest final : public SendRequest {
public:
  SimSendRequest(Delivery& d, int self, TransitPtr m, NodeStats& s)
      : delivery_(d), self_(self), msg_(std::move(m)), stats_(s) {}
  void wait() override {
    if (!msg_) return;
    const double t0 = delivery_.now();
    double t1 = t0;
    delivery_.await_arrival(self_, *msg_, t1);
    msg_ = nullptr;
    stats_.comm_s += t1 - t0;
    if (stats_.log) stats_.log->activity(Activity::Send, t0, t1);
  }
  ~SimSendRequest() override {
    if (!msg_) return;
    double now = delivery_.now();
    delivery_.await_arrival(self_, *msg_, now); // an unwaited send completes before its handle dies
  }

  // A handle is made and dropped for every send: recycled through a free list of this thread
  // instead of the heap.
  static void* operator new(std::size_t n) {
    void* p = n == sizeof(SimSendRequest) ? free_handles.take() : nullptr;
    return p ? p : ::operator new(n);
  }
  static void operator delete(void* p, std::size_t n) {
    if (n == sizeof(SimSendRequest))
      free_handles.give(p);
    else
      ::operator delete(p);
  }

private:
  static thread_local FreeList<void, OperatorDelete> free_handles;

  Delivery& delivery_;
  int self_;
  TransitPtr msg_;
  NodeStats& stats_;
};
thread_local FreeList<void, OperatorDelete> SimSendRequest::free_handles;
} // namespace

void SimComm::check_rank(int r, const char* what) const {
  if (r < 0 || r > size())
    throw std::out_of_range(std::string(what) + ": rank " + std::to_string(r) + " out of 0.." +
                            std::to_string(size()));
}

SendHandle SimComm::post(int dst, int tag, Message&& msg, std::size_t payload_bytes,
                         Blocks&& blocks, bool bundle) {
  check_rank(dst, "send");
  if (charge_payloads_) msg.charged = payload_bytes;
  // NodeStats::count_send, with the current phase's entry remembered between sends.
  if (!phase_traffic_ || traffic_phase_ != stats_.phase_changes) {
    phase_traffic_ = &stats_.phase_traffic[stats_.phase];
    traffic_phase_ = stats_.phase_changes;
  }
  stats_.bytes_sent += msg.charged;
  stats_.payload_bytes_sent += payload_bytes;
  ++stats_.messages;
  *phase_traffic_ += Traffic{msg.charged, payload_bytes, 1};
  if (stats_.log)
    stats_.log->sends.push_back(
        {dst, tag, msg.charged, message_hops(topology_, nodes_, rank_, dst), now()});
  return std::make_unique<SimSendRequest>(
      delivery_, rank_, delivery_.post(rank_, dst, tag, std::move(msg), std::move(blocks), bundle),
      stats_);
}

SendHandle SimComm::isend(int dst, int tag, Message msg) {
  const std::size_t n = msg.payload.size();
  return post(dst, tag, std::move(msg), n, {}, false);
}

SendHandle SimComm::isend_unread(int dst, int tag, std::size_t payload_bytes, std::size_t charged,
                                 bool bundle) {
  return post(dst, tag, Message{{}, charged}, payload_bytes, {}, bundle);
}

// Counted as sent the bytes the packed form would have (what the MPI backend sends).
SendHandle SimComm::isend_blocks(int dst, int tag, Blocks blocks) {
  const std::size_t n = packed_blocks_size(blocks);
  Message frame{{}, blocks_charged(blocks)};
  return post(dst, tag, std::move(frame), n, std::move(blocks), true);
}

TransitPtr SimComm::take(int src, int tag, int* from) {
  if (src != kAnySource) check_rank(src, "recv");
  const double t0 = delivery_.now();
  double t1 = t0;
  TransitPtr m = delivery_.receive(rank_, src, tag, t1);
  if (from) *from = m->src;
  stats_.comm_s += t1 - t0;
  if (stats_.log) {
    stats_.log->activity(Activity::Wait, t0, t1);
    stats_.log->recvs.push_back({m->src, m->tag, m->arrival, t1});
  }
  return m;
}

// A message of blocks received as one payload is packed, as the MPI backend would have sent it.
Message SimComm::recv_message(int src, int tag, int* from) {
  TransitPtr m = take(src, tag, from);
  if (m->bundle) return pack_blocks(m->blocks);
  return {std::move(m->data), m->charged};
}

Blocks SimComm::recv_blocks(int src, int tag, int* from) {
  TransitPtr m = take(src, tag, from);
  if (m->bundle) return std::move(m->blocks);
  return unpack_blocks({std::move(m->data), m->charged});
}

} // namespace zc
