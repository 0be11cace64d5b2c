#include "algo/tools/comm_check.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "comm/collectives.hpp"
#include "comm/wire.hpp"

namespace zc {

namespace {

Bytes block(int owner, int n) {
  Bytes b(std::size_t(n), 0);
  for (int i = 0; i < n; ++i)
    b[std::size_t(i)] = std::uint8_t(owner * 31 + i);
  return b;
}

// Failed checks, by name.
class Checks {
public:
  void operator()(bool ok, const std::string& what) {
    if (!ok) failures.push_back(what);
  }
  std::vector<std::string> failures;
};

// The collectives with a root, for three roots.
void check_rooted(Comm& c, Checks& check) {
  const int P = c.size(), r = c.rank();
  for (int root : {0, P - 1, P / 2}) {
    const std::string at = " (root " + std::to_string(root) + ")";
    check(coll::broadcast(c, root, r == root ? block(root, 300) : Bytes{}) == block(root, 300),
          "broadcast" + at);
    std::vector<Bytes> parts;
    if (r == root)
      for (int k = 0; k < P; ++k)
        parts.push_back(block(k, 10 + k));
    check(coll::scatterv(c, root, parts) == block(r, 10 + r), "scatterv" + at);
    auto g = coll::gatherv(c, root, block(r, 5 + 2 * r));
    if (r == root) {
      bool ok = int(g.size()) == P;
      for (int k = 0; ok && k < P; ++k)
        ok = g[std::size_t(k)] == block(k, 5 + 2 * k);
      check(ok, "gatherv" + at);
    }
    auto red = coll::reduce(c, root, std::vector<std::int64_t>{r, 1, -r}, coll::Op::Sum);
    if (r == root)
      check(red == (std::vector<std::int64_t>{P * (P - 1) / 2, P, -P * (P - 1) / 2}),
            "reduce" + at);
  }
}

// The collectives every node ends with a result of.
void check_all(Comm& c, Checks& check) {
  const int P = c.size(), r = c.rank();
  auto all = coll::allgatherv(c, block(r, 7 * r + 1));
  bool ok = int(all.size()) == P;
  for (int k = 0; ok && k < P; ++k)
    ok = all[std::size_t(k)] == block(k, 7 * k + 1);
  check(ok, "allgatherv");
  check(coll::allreduce(c, std::vector<std::int64_t>{r, r}, coll::Op::Max) ==
            std::vector<std::int64_t>{P - 1, P - 1},
        "allreduce max");
  check(coll::allreduce(c, std::vector<std::int64_t>{r + 5}, coll::Op::Min) ==
            std::vector<std::int64_t>{5},
        "allreduce min");
  auto d = coll::allreduce(c, std::vector<double>{0.1 * r, 1.0 / (r + 1)}, coll::Op::Sum);
  check(d == coll::allreduce(c, d, coll::Op::Max), "allreduce: every node holds the same bits");
  check(coll::prefix_sum(c, std::vector<std::int64_t>{1, r}) ==
            std::vector<std::int64_t>{r + 1, std::int64_t(r) * (r + 1) / 2},
        "prefix_sum");
  for (auto how : {coll::AllToAll::Direct, coll::AllToAll::Pairwise}) {
    std::vector<Bytes> out;
    for (int k = 0; k < P; ++k)
      out.push_back(block(r * 100 + k, (r + k) % 5));
    auto in = coll::alltoallv(c, out, how);
    bool a2a = int(in.size()) == P;
    for (int k = 0; a2a && k < P; ++k)
      a2a = in[std::size_t(k)] == block(k * 100 + r, (k + r) % 5);
    check(a2a, how == coll::AllToAll::Direct ? "alltoallv direct" : "alltoallv pairwise");
  }
}

void check_point_to_point(Comm& c, Checks& check) {
  const int P = c.size(), r = c.rank();
  // Three messages per (source, tag) on two tags arrive in order, from any source.
  constexpr int kTagA = 900, kTagB = 901, kCount = 3;
  if (P > 1) {
    const int next = (r + 1) % P, prev = (r + P - 1) % P;
    std::vector<SendHandle> hs;
    for (int i = 0; i < kCount; ++i)
      for (int tag : {kTagA, kTagB})
        hs.push_back(c.isend(next, tag, pack(std::vector<std::int32_t>{r, tag, i})));
    for (int tag : {kTagB, kTagA})
      for (int i = 0; i < kCount; ++i) {
        int from = -2;
        auto v = unpack<std::int32_t>(c.recv(i == 0 ? kAnySource : prev, tag, &from));
        check(from == prev && v == std::vector<std::int32_t>{prev, tag, i},
              "FIFO per (source, tag)");
      }
    for (auto& h : hs)
      h->wait();
  }
  // Two nodes that both send (blocking) before they receive: a send never waits for its
  // receiver, even for a message too large for a transport's eager buffers.
  if (const int partner = r ^ 1; partner < P && P > 1) {
    constexpr int kTagSwap = 902;
    c.send(partner, kTagSwap, block(r, 1 << 20));
    check(c.recv(partner, kTagSwap) == block(partner, 1 << 20), "crossing blocking sends of 1 MiB");
  }
}

// Charged sizes travel with the blocks they charge (comm/comm.hpp), whatever the backend.
void check_charged(Comm& c, Checks& check) {
  const int P = c.size(), r = c.rank();
  auto g = coll::gatherv(c, 0, Message{block(r, 3 + r), std::size_t(1000 + r)});
  if (r == 0) {
    bool ok = int(g.size()) == P;
    for (int k = 0; ok && k < P; ++k)
      ok = g[std::size_t(k)].payload == block(k, 3 + k) && g[std::size_t(k)].charged == 1000u + k;
    check(ok, "gatherv of charged blocks");
  }
  auto all = coll::alltoallv(c, std::vector<Message>(std::size_t(P), Message{block(r, 2), 77}));
  bool ok = int(all.size()) == P;
  for (int k = 0; ok && k < P; ++k)
    ok = all[std::size_t(k)].payload == block(k, 2) && all[std::size_t(k)].charged == 77;
  check(ok, "alltoallv of charged blocks");
}

void comm_check_node(NodeContext& ctx) {
  Comm& c = ctx.comm();
  Checks check;
  check_rooted(c, check);
  check_all(c, check);
  check_charged(c, check);
  check_point_to_point(c, check);
  coll::barrier(c);
  ctx.metrics()["comm_check_failures"] = check.failures;
  if (!check.failures.empty())
    throw std::runtime_error(std::to_string(check.failures.size()) +
                             " wrong communications, first: " + check.failures.front());
}

} // namespace

Algorithm comm_check_algorithm() {
  Algorithm a;
  a.name = "comm-check";
  a.summary = "self-test: every collective and FIFO point-to-point order, data checked";
  a.node = comm_check_node;
  a.draws_picture = false;
  return a;
}

} // namespace zc
