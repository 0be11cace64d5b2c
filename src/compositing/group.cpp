#include "compositing/group.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace zc::compositing {

namespace {

// True when member g = member 0 XOR (the world bits of g's bits), each group bit one world bit.
bool is_subcube(const std::vector<int>& m) {
  if (!std::has_single_bit(m.size())) return false;
  for (std::size_t b = 1; b < m.size(); b <<= 1)
    if (!std::has_single_bit(unsigned(m[b] ^ m[0]))) return false;
  for (std::size_t g = 0; g < m.size(); ++g) {
    int w = m[0];
    for (std::size_t b = 1; b < m.size(); b <<= 1)
      if (g & b) w ^= m[b] ^ m[0];
    if (m[g] != w) return false;
  }
  return true;
}

} // namespace

GroupComm::GroupComm(Comm& world, std::vector<int> members)
    : world_(world), members_(std::move(members)) {
  auto it = std::find(members_.begin(), members_.end(), world.rank());
  if (it == members_.end()) throw std::invalid_argument("GroupComm: this node is no member");
  rank_ = int(it - members_.begin());
  topology_ =
      world.topology() == Topology::Cube && is_subcube(members_) ? Topology::Cube : Topology::Ring;
}

SendHandle GroupComm::isend(int dst, int tag, Message m) {
  return world_.isend(world_rank(dst), tag, std::move(m));
}

void GroupComm::send(int dst, int tag, Message m) {
  world_.send(world_rank(dst), tag, std::move(m));
}

Message GroupComm::recv_message(int src, int tag, int* from) {
  int w = -1;
  Message m = world_.recv_message(src == kAnySource ? kAnySource : world_rank(src), tag, &w);
  if (from) {
    auto it = std::find(members_.begin(), members_.end(), w);
    if (it == members_.end()) throw std::logic_error("GroupComm: message from outside the group");
    *from = int(it - members_.begin());
  }
  return m;
}

std::vector<int> digit_group(int rank, const std::vector<int>& factors, int digit) {
  int stride = 1;
  for (int j = 0; j < digit; ++j)
    stride *= factors[std::size_t(j)];
  const int k = factors[std::size_t(digit)];
  const int base = rank - ((rank / stride) % k) * stride;
  std::vector<int> members;
  for (int v = 0; v < k; ++v)
    members.push_back(base + v * stride);
  return members;
}

} // namespace zc::compositing
