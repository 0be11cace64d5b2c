#pragma once
// Global communications of PPCM (Charles et al. §3), each written for the hypercube (recursive
// doubling/halving over the channels, log2 P steps) and for the ring (P-1 or P/2 neighbour steps).
// Every node of the machine calls the same collective with the same root and tag.
//
// Each block collective comes in two forms: on payloads (charged as their size), and on Messages,
// whose charged sizes travel with the blocks: a message that forwards several blocks is charged
// their charged sizes plus its framing (a count, and an owner and a length a block: 4 + 12 bytes
// a block), so the default (payload = charged) charges the payload's size as before.
#include <cstdint>
#include <vector>

#include "comm/comm.hpp"

namespace zc::coll {

// Tags at or above kCollectiveTagBase are reserved for collectives.
constexpr int kCollectiveTagBase = 1 << 20;

// Root's `data` reaches every node (returned everywhere).
Bytes broadcast(Comm& c, int root, Bytes data, int tag = kCollectiveTagBase + 1);
Message broadcast(Comm& c, int root, Message data, int tag = kCollectiveTagBase + 1);

// Root holds one block per node (parts.size() == size at root, ignored elsewhere); each node
// gets its block.
Bytes scatterv(Comm& c, int root, std::vector<Bytes> parts, int tag = kCollectiveTagBase + 2);
Message scatterv(Comm& c, int root, std::vector<Message> parts, int tag = kCollectiveTagBase + 2);

// Every node's block arrives at root (returned there, indexed by rank; empty elsewhere).
std::vector<Bytes> gatherv(Comm& c, int root, Bytes mine, int tag = kCollectiveTagBase + 3);
std::vector<Message> gatherv(Comm& c, int root, Message mine, int tag = kCollectiveTagBase + 3);

// Multi-broadcast (all-gather v): every node gets every node's block, indexed by rank.
std::vector<Bytes> allgatherv(Comm& c, Bytes mine, int tag = kCollectiveTagBase + 4);
std::vector<Message> allgatherv(Comm& c, Message mine, int tag = kCollectiveTagBase + 4);

enum class Op { Sum, Min, Max };

// Element-wise reduction to root (result at root only) and multi-reduce (result everywhere).
// Operands are combined in one fixed order on every node, so doubles are bit-identical too.
std::vector<std::int64_t> reduce(Comm& c, int root, std::vector<std::int64_t> v, Op op,
                                 int tag = kCollectiveTagBase + 5);
std::vector<double> reduce(Comm& c, int root, std::vector<double> v, Op op,
                           int tag = kCollectiveTagBase + 6);
std::vector<std::int64_t> allreduce(Comm& c, std::vector<std::int64_t> v, Op op,
                                    int tag = kCollectiveTagBase + 7);
std::vector<double> allreduce(Comm& c, std::vector<double> v, Op op,
                              int tag = kCollectiveTagBase + 8);
// 32-bit entries (the papers' row loads and pixel counts are C ints: 4 bytes each on the wire).
std::vector<std::int32_t> allreduce(Comm& c, std::vector<std::int32_t> v, Op op,
                                    int tag = kCollectiveTagBase + 7);

// Inclusive prefix sum over ranks, element-wise: node r gets v_0 + ... + v_r.
std::vector<std::int64_t> prefix_sum(Comm& c, std::vector<std::int64_t> v,
                                     int tag = kCollectiveTagBase + 9);

enum class AllToAll {
  Direct,  // every node isends all its blocks at once, then receives
  Pairwise // P-1 steps; at step k node r exchanges with r XOR k (cube: disjoint e-cube paths,
           // the schedule Kurc et al. §3.2 cite from Abali et al.); ring: shift by k
};
// All-to-all personalised: out[d] goes to node d; returns in[s] from each node s.
std::vector<Bytes> alltoallv(Comm& c, std::vector<Bytes> out, AllToAll how = AllToAll::Pairwise,
                             int tag = kCollectiveTagBase + 10);
std::vector<Message> alltoallv(Comm& c, std::vector<Message> out, AllToAll how = AllToAll::Pairwise,
                               int tag = kCollectiveTagBase + 10);

// All nodes wait for each other (a zero-byte all-reduce).
void barrier(Comm& c, int tag = kCollectiveTagBase + 11);

} // namespace zc::coll
