// comm/collectives on the in-process Comm: every collective's result on every node of rings of 1
// to 16 nodes and cubes of 1 to 16, from several roots, on payloads and on charged messages. (The
// simulator's tests, test_collectives.cpp, time them.)
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "comm/collectives.hpp"
#include "comm/local_comm.hpp"

using namespace zc;

namespace {

struct Shape {
  int nodes;
  Topology topology;
  std::string name() const {
    return std::string(topology_name(topology)) + " of " + std::to_string(nodes);
  }
};

// Rings of 1..16 nodes and cubes of 1, 2, 4, 8, 16.
std::vector<Shape> shapes() {
  std::vector<Shape> v;
  for (int p = 1; p <= 16; ++p) {
    v.push_back({p, Topology::Ring});
    if ((p & (p - 1)) == 0) v.push_back({p, Topology::Cube});
  }
  return v;
}

// A block that differs by node and by purpose: n bytes of `fill`.
Bytes block(int n, int fill) {
  return Bytes(std::size_t(n), std::uint8_t(fill));
}

// Runs `check` on every rank of every shape; it returns what it found wrong, "" when nothing.
template <class Check> void on_every_shape(Check check) {
  for (const Shape& s : shapes()) {
    std::vector<std::string> wrong(std::size_t(s.nodes));
    run_local(s.nodes, s.topology, [&](Comm& c) { wrong[std::size_t(c.rank())] = check(c); });
    for (int r = 0; r < s.nodes; ++r)
      EXPECT_EQ(wrong[std::size_t(r)], "") << s.name() << ", rank " << r;
  }
}

std::vector<int> roots(int p) {
  return p == 1 ? std::vector<int>{0} : std::vector<int>{0, p - 1, p / 2};
}

} // namespace

TEST(LocalCollectives, BroadcastScatterAndGatherFromEveryRoot) {
  on_every_shape([](Comm& c) -> std::string {
    const int p = c.size(), k = c.rank();
    for (int root : roots(p)) {
      if (coll::broadcast(c, root, k == root ? block(9, root) : Bytes{}) != block(9, root))
        return "broadcast from " + std::to_string(root);
      std::vector<Bytes> parts;
      if (k == root)
        for (int i = 0; i < p; ++i)
          parts.push_back(block(i + 1, i));
      if (coll::scatterv(c, root, parts) != block(k + 1, k))
        return "scatterv from " + std::to_string(root);
      const auto g = coll::gatherv(c, root, block(k % 4, k));
      for (int i = 0; i < p && k == root; ++i)
        if (g.at(std::size_t(i)) != block(i % 4, i)) return "gatherv to " + std::to_string(root);
      if (k != root && !g.empty()) return "gatherv left blocks off the root";
    }
    return "";
  });
}

TEST(LocalCollectives, AllGatherAllToAllAndBarrier) {
  on_every_shape([](Comm& c) -> std::string {
    const int p = c.size(), k = c.rank();
    const auto all = coll::allgatherv(c, block(k % 3, 40 + k));
    for (int i = 0; i < p; ++i)
      if (all.at(std::size_t(i)) != block(i % 3, 40 + i)) return "allgatherv";
    for (auto how : {coll::AllToAll::Direct, coll::AllToAll::Pairwise}) {
      std::vector<Bytes> out;
      for (int d = 0; d < p; ++d)
        out.push_back(block((k + d) % 4, 16 * k + d));
      const auto in = coll::alltoallv(c, out, how);
      for (int s = 0; s < p; ++s)
        if (in.at(std::size_t(s)) != block((s + k) % 4, 16 * s + k)) return "alltoallv";
    }
    coll::barrier(c);
    return "";
  });
}

TEST(LocalCollectives, ReductionsAndPrefixSums) {
  on_every_shape([](Comm& c) -> std::string {
    const int p = c.size(), k = c.rank();
    const std::int64_t sum = std::int64_t(p) * (p - 1) / 2;
    for (int root : roots(p)) {
      const auto mx =
          coll::reduce(c, root, std::vector<double>{double(k), -0.5 * k}, coll::Op::Max);
      if (k == root && mx != std::vector<double>{double(p - 1), 0.0}) return "reduce max";
      const auto s = coll::reduce(c, root, std::vector<std::int64_t>{k, 1}, coll::Op::Sum);
      if (k == root && s != std::vector<std::int64_t>{sum, p}) return "reduce sum";
    }
    if (coll::allreduce(c, std::vector<std::int64_t>{k, -k}, coll::Op::Min) !=
        std::vector<std::int64_t>{0, 1 - p})
      return "allreduce min";
    if (coll::allreduce(c, std::vector<std::int32_t>{1, k}, coll::Op::Sum) !=
        std::vector<std::int32_t>{p, std::int32_t(sum)})
      return "allreduce int32 sum";
    if (coll::allreduce(c, std::vector<double>{0.5 * k}, coll::Op::Sum) !=
        std::vector<double>{0.5 * double(sum)})
      return "allreduce double sum";
    if (coll::prefix_sum(c, std::vector<std::int64_t>{2, k}) !=
        std::vector<std::int64_t>{2 * (k + 1), std::int64_t(k) * (k + 1) / 2})
      return "prefix_sum";
    return "";
  });
}

TEST(LocalCollectives, ChargedSizesTravelWithTheBlocks) {
  on_every_shape([](Comm& c) -> std::string {
    const int p = c.size(), k = c.rank();
    const Message b = coll::broadcast(c, 0, Message{block(8, 1), 3});
    if (b.charged != 3 || b.payload != block(8, 1)) return "broadcast's charged size";
    const auto g = coll::allgatherv(c, Message{block(k, k), std::size_t(100 + k)});
    for (int i = 0; i < p; ++i)
      if (g.at(std::size_t(i)).charged != std::size_t(100 + i)) return "allgatherv's charged size";
    std::vector<Message> out;
    for (int d = 0; d < p; ++d)
      out.push_back({block(2, d), std::size_t(1000 * k + d)});
    const auto in = coll::alltoallv(c, out);
    for (int s = 0; s < p; ++s)
      if (in.at(std::size_t(s)).charged != std::size_t(1000 * s + k)) return "alltoallv's charged";
    return "";
  });
}
