#pragma once
// SimGrid backend of the communication layer: messages travel through Delivery (no actor per
// message under the analytic and circuit fidelities); a blocking send returns when its message
// has arrived, as does waiting on an asynchronous send's handle.
#include <simgrid/s4u.hpp>

#include "comm/comm.hpp"
#include "run/report.hpp"
#include "sim/delivery.hpp"

namespace zc {

class SimComm final : public Comm {
public:
  // `charge_payloads`: every message charged its payload's bytes instead of its records'
  // (NetworkParams::charge_payloads).
  SimComm(int rank, int nodes, Topology topology, Delivery& delivery, NodeStats& stats,
          bool charge_payloads = false)
      : rank_(rank), nodes_(nodes), topology_(topology), delivery_(delivery), stats_(stats),
        charge_payloads_(charge_payloads) {}

  int rank() const override { return rank_; }
  int size() const override { return nodes_; }
  Topology topology() const override { return topology_; }
  using Comm::isend;
  using Comm::send;
  SendHandle isend(int dst, int tag, Message m) override;
  Message recv_message(int src, int tag, int* from) override;
  // The blocks travel as they are: their payloads are shared, not packed (nor copied).
  SendHandle isend_blocks(int dst, int tag, Blocks blocks) override;
  void send_blocks(int dst, int tag, Blocks blocks) override {
    isend_blocks(dst, tag, std::move(blocks))->wait();
  }
  Blocks recv_blocks(int src, int tag, int* from) override;
  double now() const override { return delivery_.now(); }
  Delivery& delivery() const { return delivery_; }
  // The next message from src (or kAnySource) with this tag, taken as the receives above take it
  // (a replay drops it unread: sim/replay.hpp).
  TransitPtr take(int src, int tag, int* from);
  // A replay's send (sim/replay.hpp): a message (or a bundle of blocks) counted and charged as the
  // recorded one, with no bytes behind it, since nobody reads a replay's messages: dummy buffers
  // of the recorded sizes would be written, and their pages faulted in, for nothing.
  SendHandle isend_unread(int dst, int tag, std::size_t payload_bytes, std::size_t charged,
                          bool bundle);

private:
  void check_rank(int r, const char* what) const;
  // By reference: moved on once, into the message's Transit (no moved-from copy a level).
  SendHandle post(int dst, int tag, Message&& m, std::size_t payload_bytes, Blocks&& blocks,
                  bool bundle);

  int rank_, nodes_;
  Topology topology_;
  Delivery& delivery_;
  NodeStats& stats_;
  // stats_.phase_traffic[stats_.phase], while stats_.phase_changes stays traffic_phase_.
  Traffic* phase_traffic_ = nullptr;
  std::uint64_t traffic_phase_ = 0;
  bool charge_payloads_;
};

} // namespace zc
