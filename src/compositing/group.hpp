#pragma once
// A group of nodes as a Comm of its own (IceT's compose groups): group rank g is world rank
// members[g], so the collectives of src/comm run unchanged within a subcube or any subset. The
// group is a hypercube when its members are a subcube whose group ranks follow the world's
// channels (member g = member 0 XOR the world bits of g), else a ring: that only picks the
// collectives' schedule, the messages travel the machine's own routes.
#include <vector>

#include "comm/comm.hpp"

namespace zc::compositing {

class GroupComm : public Comm {
public:
  // `world` must outlive the group; this node must be one of `members` (distinct world ranks).
  GroupComm(Comm& world, std::vector<int> members);

  int rank() const override { return rank_; }
  int size() const override { return int(members_.size()); }
  Topology topology() const override { return topology_; }
  SendHandle isend(int dst, int tag, Message m) override;
  Message recv_message(int src, int tag, int* from = nullptr) override;
  void send(int dst, int tag, Message m) override;
  double now() const override { return world_.now(); }

  int world_rank(int g) const { return members_.at(std::size_t(g)); }
  const std::vector<int>& members() const { return members_; }

private:
  Comm& world_;
  std::vector<int> members_;
  int rank_ = -1;
  Topology topology_ = Topology::Ring;
};

// The world ranks whose rank agrees with `rank` everywhere but in the mixed-radix digit `digit`
// of the factors (digit 0 the least significant), in the order of that digit: a round's group of
// radix-k (k = factors[digit]); with factors of 2, the subcube over one channel.
std::vector<int> digit_group(int rank, const std::vector<int>& factors, int digit);

} // namespace zc::compositing
