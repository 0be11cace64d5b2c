#pragma once
// SimGrid backend of the communication layer. Each message is carried by a small transport actor
// that spends the network's time (SimNetwork) and then drops the payload into the destination's
// mailbox; mailboxes are eager (their owner is the permanent receiver), and receivers reorder by
// per-(source, tag) sequence numbers, so messages never overtake each other on one (source, tag).
#include <cstdint>
#include <deque>
#include <map>

#include <simgrid/s4u.hpp>

#include "comm/comm.hpp"
#include "sim/report.hpp"
#include "sim/sim_network.hpp"

namespace zc {

class SimComm final : public Comm {
public:
  SimComm(int rank, SimNetwork& net, NodeStats& stats);

  int rank() const override { return rank_; }
  int size() const override { return net_.nodes(); }
  Topology topology() const override { return net_.topology(); }
  void send(int dst, int tag, Bytes data) override;
  SendHandle isend(int dst, int tag, Bytes data) override;
  Bytes recv(int src, int tag, int* from) override;
  double now() const override { return simgrid::s4u::Engine::get_clock(); }

  // Must run in the owning actor before anyone sends to it.
  void attach();
  static std::string mailbox_name(int rank) { return "rank" + std::to_string(rank); }

private:
  struct Message {
    int src, tag;
    std::uint64_t seq;
    Bytes data;
  };
  void check_rank(int r, const char* what) const;

  int rank_;
  SimNetwork& net_;
  NodeStats& stats_;
  simgrid::s4u::Mailbox* mbox_ = nullptr;
  std::map<std::pair<int, int>, std::uint64_t> next_send_; // (dst, tag) -> seq
  std::map<std::pair<int, int>, std::uint64_t> next_recv_; // (src, tag) -> seq
  std::deque<Message*> stash_;                             // arrived, not yet received
};

} // namespace zc
