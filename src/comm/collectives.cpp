#include "comm/collectives.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "comm/wire.hpp"

namespace zc::coll {
namespace {

// Several blocks travel as one message (Comm::isend_blocks): charged their framing as a program
// would send it (the count, and an owner and a length a block: 4 + 12 bytes a block) plus the sum
// of the blocks' charged sizes; each block keeps its charged size, so that the node a block reaches
// charges it again, and its payload, which the simulator shares instead of copying.

// Each part a message charged as its payload's size (charged_as_payload).
std::vector<Message> charged_as_payloads(std::vector<Bytes> parts) {
  std::vector<Message> m;
  m.reserve(parts.size());
  for (auto& b : parts)
    m.push_back(charged_as_payload(std::move(b)));
  return m;
}

std::vector<Bytes> payloads(std::vector<Message> m) {
  std::vector<Bytes> b;
  b.reserve(m.size());
  for (auto& x : m)
    b.push_back(std::move(x.payload).take());
  return b;
}

bool cube(const Comm& c) {
  return c.topology() == Topology::Cube;
}
int P(const Comm& c) {
  return c.size();
}

// Relative numbering around a root: XOR on the cube (keeps channels), rotation on the ring.
int rel_of(const Comm& c, int rank, int root) {
  return cube(c) ? (rank ^ root) : (rank - root + P(c)) % P(c);
}
int abs_of(const Comm& c, int rel, int root) {
  return cube(c) ? (rel ^ root) : (rel + root) % P(c);
}

// Ring arms around the root: relative ranks 1..R go right (+1), P-L..P-1 go left.
int right_arm(int p) {
  return p / 2;
}

template <class T>
void combine(std::vector<T>& acc, const std::vector<T>& lo_first, Op op, bool acc_is_low) {
  // acc = op(low, high) element-wise, where `acc_is_low` says which operand acc holds.
  if (acc.size() != lo_first.size()) throw std::runtime_error("reduce: vector sizes differ");
  for (std::size_t i = 0; i < acc.size(); ++i) {
    const T a = acc_is_low ? acc[i] : lo_first[i];
    const T b = acc_is_low ? lo_first[i] : acc[i];
    switch (op) {
    case Op::Sum:
      acc[i] = a + b;
      break;
    case Op::Min:
      acc[i] = std::min(a, b);
      break;
    case Op::Max:
      acc[i] = std::max(a, b);
      break;
    }
  }
}

template <class T> std::vector<T> reduce_impl(Comm& c, int root, std::vector<T> v, Op op, int tag) {
  const int p = P(c), r = c.rank();
  if (p == 1) return v;
  const int rel = rel_of(c, r, root);
  if (cube(c)) {
    // Binomial tree: at step i, relative ranks with bit i set send to rel ^ 2^i and stop.
    for (int i = 0; (1 << i) < p; ++i) {
      const int bit = 1 << i;
      if (rel & (bit - 1)) break;
      if (rel & bit) {
        c.send(abs_of(c, rel ^ bit, root), tag, pack(v));
        return {};
      }
      auto other = unpack<T>(c.recv(abs_of(c, rel ^ bit, root), tag));
      combine(v, other, op, true); // the receiver is the lower relative rank
    }
    return v;
  }
  // Ring: both arms accumulate towards the root, far end first.
  const int R = right_arm(p);
  if (rel != 0) {
    const bool right = rel <= R;
    const int farther = right ? rel + 1 : rel - 1;
    const bool has_farther = right ? (rel < R) : (rel > R + 1);
    if (has_farther) {
      auto other = unpack<T>(c.recv(abs_of(c, farther, root), tag));
      combine(v, other, op, true);
    }
    c.send(abs_of(c, right ? rel - 1 : (rel + 1) % p, root), tag, pack(v));
    return {};
  }
  if (R >= 1) combine(v, unpack<T>(c.recv(abs_of(c, 1, root), tag)), op, true);
  if (p - 1 > R) combine(v, unpack<T>(c.recv(abs_of(c, p - 1, root), tag)), op, true);
  return v;
}

template <class T> std::vector<T> allreduce_impl(Comm& c, std::vector<T> v, Op op, int tag) {
  const int p = P(c), r = c.rank();
  if (p == 1) return v;
  if (cube(c)) {
    // Recursive doubling; both partners compute op(lower rank's, higher rank's): same bits.
    for (int i = 0; (1 << i) < p; ++i) {
      const int partner = r ^ (1 << i);
      auto h = c.isend(partner, tag, pack(v));
      auto other = unpack<T>(c.recv(partner, tag));
      h->wait();
      combine(v, other, op, r < partner);
    }
    return v;
  }
  auto red = reduce_impl(c, 0, std::move(v), op, tag);
  return unpack<T>(broadcast(c, 0, pack(red), tag));
}

} // namespace

Message broadcast(Comm& c, int root, Message data, int tag) {
  const int p = P(c), r = c.rank();
  if (p == 1) return data;
  const int rel = rel_of(c, r, root);
  if (cube(c)) {
    for (int i = 0; (1 << i) < p; ++i) {
      const int bit = 1 << i;
      if (rel < bit) {
        c.send(abs_of(c, rel | bit, root), tag, data);
      } else if (rel < 2 * bit) {
        data = c.recv_message(abs_of(c, rel ^ bit, root), tag);
      }
    }
    return data;
  }
  const int R = right_arm(p);
  if (rel == 0) {
    SendHandle h;
    if (p - 1 > R) h = c.isend(abs_of(c, p - 1, root), tag, data);
    if (R >= 1) c.send(abs_of(c, 1, root), tag, data);
    if (h) h->wait();
    return data;
  }
  const bool right = rel <= R;
  data = c.recv_message(abs_of(c, right ? rel - 1 : (rel + 1) % p, root), tag);
  if (right ? rel < R : rel > R + 1) c.send(abs_of(c, right ? rel + 1 : rel - 1, root), tag, data);
  return data;
}

Bytes broadcast(Comm& c, int root, Bytes data, int tag) {
  return broadcast(c, root, charged_as_payload(std::move(data)), tag).payload;
}

Message scatterv(Comm& c, int root, std::vector<Message> parts, int tag) {
  const int p = P(c), r = c.rank();
  if (r == root && int(parts.size()) != p)
    throw std::invalid_argument("scatterv: the root needs one block per node");
  if (p == 1) return std::move(parts[0]);
  const int rel = rel_of(c, r, root);
  Blocks mine; // blocks this node holds, by relative owner
  if (rel == 0)
    for (int k = 0; k < p; ++k)
      mine.push_back({k, std::move(parts[abs_of(c, k, root)])});
  if (cube(c)) {
    // Recursive halving: the holder of a subcube of 2^(i+1) ranks sends the upper 2^i blocks.
    const int d = log2_exact(p);
    for (int i = d - 1; i >= 0; --i) {
      const int bit = 1 << i;
      if ((rel & (2 * bit - 1)) == 0) {
        Blocks keep, give;
        for (auto& b : mine)
          ((b.owner & bit) ? give : keep).push_back(std::move(b));
        c.send_blocks(abs_of(c, rel | bit, root), tag, std::move(give));
        mine = std::move(keep);
      } else if ((rel & (2 * bit - 1)) == bit) {
        mine = c.recv_blocks(abs_of(c, rel ^ bit, root), tag);
      }
    }
  } else {
    const int R = right_arm(p);
    if (rel == 0) {
      Blocks right, left;
      for (auto& b : mine)
        if (b.owner != 0) (b.owner <= R ? right : left).push_back(std::move(b));
      std::erase_if(mine, [](const Block& b) { return b.owner != 0; });
      SendHandle h;
      if (!left.empty()) h = c.isend_blocks(abs_of(c, p - 1, root), tag, std::move(left));
      if (!right.empty()) c.send_blocks(abs_of(c, 1, root), tag, std::move(right));
      if (h) h->wait();
    } else {
      const bool right = rel <= R;
      mine = c.recv_blocks(abs_of(c, right ? rel - 1 : (rel + 1) % p, root), tag);
      Blocks rest;
      for (auto& b : mine)
        if (b.owner != rel) rest.push_back(std::move(b));
      std::erase_if(mine, [&](const Block& b) { return b.owner != rel; });
      if (!rest.empty())
        c.send_blocks(abs_of(c, right ? rel + 1 : rel - 1, root), tag, std::move(rest));
    }
  }
  for (auto& b : mine)
    if (b.owner == rel) return std::move(b.data);
  throw std::logic_error("scatterv: block lost");
}

Bytes scatterv(Comm& c, int root, std::vector<Bytes> parts, int tag) {
  return scatterv(c, root, charged_as_payloads(std::move(parts)), tag).payload;
}

std::vector<Message> gatherv(Comm& c, int root, Message data, int tag) {
  const int p = P(c), r = c.rank();
  std::vector<Message> out;
  if (p == 1) {
    out.push_back(std::move(data));
    return out;
  }
  const int rel = rel_of(c, r, root);
  Blocks mine{{rel, std::move(data)}};
  if (cube(c)) {
    for (int i = 0; (1 << i) < p; ++i) {
      const int bit = 1 << i;
      if (rel & (bit - 1)) break;
      if (rel & bit) {
        c.send_blocks(abs_of(c, rel ^ bit, root), tag, std::move(mine));
        return {};
      }
      for (auto& b : c.recv_blocks(abs_of(c, rel ^ bit, root), tag))
        mine.push_back(std::move(b));
    }
  } else {
    const int R = right_arm(p);
    if (rel != 0) {
      const bool right = rel <= R;
      if (right ? rel < R : rel > R + 1)
        for (auto& b : c.recv_blocks(abs_of(c, right ? rel + 1 : rel - 1, root), tag))
          mine.push_back(std::move(b));
      c.send_blocks(abs_of(c, right ? rel - 1 : (rel + 1) % p, root), tag, std::move(mine));
      return {};
    }
    if (R >= 1)
      for (auto& b : c.recv_blocks(abs_of(c, 1, root), tag))
        mine.push_back(std::move(b));
    if (p - 1 > R)
      for (auto& b : c.recv_blocks(abs_of(c, p - 1, root), tag))
        mine.push_back(std::move(b));
  }
  out.resize(p);
  for (auto& b : mine)
    out[abs_of(c, b.owner, root)] = std::move(b.data);
  return out;
}

std::vector<Bytes> gatherv(Comm& c, int root, Bytes data, int tag) {
  return payloads(gatherv(c, root, charged_as_payload(std::move(data)), tag));
}

std::vector<Message> allgatherv(Comm& c, Message data, int tag) {
  const int p = P(c), r = c.rank();
  std::vector<Message> out(p);
  if (cube(c)) {
    Blocks mine{{r, std::move(data)}};
    for (int i = 0; (1 << i) < p; ++i) {
      const int partner = r ^ (1 << i);
      auto h = c.isend_blocks(partner, tag, mine); // copies references, not bytes
      for (auto& b : c.recv_blocks(partner, tag))
        mine.push_back(std::move(b));
      h->wait();
    }
    for (auto& b : mine)
      out[b.owner] = std::move(b.data);
    return out;
  }
  // Ring: P-1 steps, each passing to the right the block received at the previous step.
  out[r] = std::move(data);
  int have = r;
  const int right = (r + 1) % p, left = (r + p - 1) % p;
  for (int s = 1; s < p; ++s) {
    auto h = c.isend(right, tag, out[have]);
    const int from = (r - s + p) % p;
    out[from] = c.recv_message(left, tag);
    h->wait();
    have = from;
  }
  return out;
}

std::vector<Bytes> allgatherv(Comm& c, Bytes data, int tag) {
  return payloads(allgatherv(c, charged_as_payload(std::move(data)), tag));
}

std::vector<std::int64_t> reduce(Comm& c, int root, std::vector<std::int64_t> v, Op op, int tag) {
  return reduce_impl(c, root, std::move(v), op, tag);
}
std::vector<double> reduce(Comm& c, int root, std::vector<double> v, Op op, int tag) {
  return reduce_impl(c, root, std::move(v), op, tag);
}
std::vector<std::int64_t> allreduce(Comm& c, std::vector<std::int64_t> v, Op op, int tag) {
  return allreduce_impl(c, std::move(v), op, tag);
}
std::vector<double> allreduce(Comm& c, std::vector<double> v, Op op, int tag) {
  return allreduce_impl(c, std::move(v), op, tag);
}
std::vector<std::int32_t> allreduce(Comm& c, std::vector<std::int32_t> v, Op op, int tag) {
  return allreduce_impl(c, std::move(v), op, tag);
}

std::vector<std::int64_t> prefix_sum(Comm& c, std::vector<std::int64_t> v, int tag) {
  const int p = P(c), r = c.rank();
  if (p == 1) return v;
  if (cube(c)) {
    // Hypercube scan: keep the running subcube total; add what lower partners held.
    std::vector<std::int64_t> total = v;
    for (int i = 0; (1 << i) < p; ++i) {
      const int partner = r ^ (1 << i);
      auto h = c.isend(partner, tag, pack(total));
      auto other = unpack<std::int64_t>(c.recv(partner, tag));
      h->wait();
      for (std::size_t k = 0; k < v.size(); ++k) {
        if (partner < r) v[k] += other[k];
        total[k] += other[k];
      }
    }
    return v;
  }
  if (r > 0) {
    auto before = unpack<std::int64_t>(c.recv(r - 1, tag));
    for (std::size_t k = 0; k < v.size(); ++k)
      v[k] += before[k];
  }
  if (r + 1 < p) c.send(r + 1, tag, pack(v));
  return v;
}

std::vector<Message> alltoallv(Comm& c, std::vector<Message> out, AllToAll how, int tag) {
  const int p = P(c), r = c.rank();
  if (int(out.size()) != p) throw std::invalid_argument("alltoallv: one block per node");
  std::vector<Message> in(p);
  in[r] = std::move(out[r]);
  if (how == AllToAll::Direct) {
    std::vector<SendHandle> hs;
    for (int k = 1; k < p; ++k) {
      const int d = (r + k) % p;
      hs.push_back(c.isend(d, tag, std::move(out[d])));
    }
    for (int k = 1; k < p; ++k) {
      const int s = (r - k + p) % p;
      in[s] = c.recv_message(s, tag);
    }
    for (auto& h : hs)
      h->wait();
    return in;
  }
  for (int k = 1; k < p; ++k) {
    const int to = cube(c) ? (r ^ k) : (r + k) % p;
    const int from = cube(c) ? (r ^ k) : (r - k + p) % p;
    auto h = c.isend(to, tag, std::move(out[to]));
    in[from] = c.recv_message(from, tag);
    h->wait();
  }
  return in;
}

std::vector<Bytes> alltoallv(Comm& c, std::vector<Bytes> out, AllToAll how, int tag) {
  return payloads(alltoallv(c, charged_as_payloads(std::move(out)), how, tag));
}

void barrier(Comm& c, int tag) {
  allreduce(c, std::vector<std::int64_t>{}, Op::Sum, tag);
}

} // namespace zc::coll
