// run_local's ranks: a mailbox a rank, scanned in arrival order for the first message that
// matches a receive, so the messages of one source and tag are taken in the order they were sent.
#include "comm/local_comm.hpp"

#include <atomic>
#include <bit>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace zc {

namespace {

using Clock = std::chrono::steady_clock;

struct Envelope {
  int src, tag;
  Message message;
};

struct Mailbox {
  std::mutex lock;
  std::condition_variable arrived;
  std::deque<Envelope> queue;
};

// What the ranks of one run share.
struct World {
  World(int nodes, Topology topology, LocalRun options)
      : nodes(nodes), topology(topology), options(options),
        boxes(std::size_t(nodes + (options.host ? 1 : 0))) {}

  // The first failure is kept; every waiting rank is woken to fail too.
  void fail(std::exception_ptr e) {
    {
      std::lock_guard g(failure_lock);
      if (!failure) failure = e;
    }
    for (auto& b : boxes) {
      std::lock_guard g(b.lock);
      failed = true;
      b.arrived.notify_all();
    }
  }

  const int nodes;
  const Topology topology;
  const LocalRun options;
  const Clock::time_point start = Clock::now();
  std::vector<Mailbox> boxes;
  std::atomic<bool> failed = false; // set under every mailbox's lock before its wake-up
  std::mutex failure_lock;
  std::exception_ptr failure;
};

// The message is in its receiver's mailbox when isend returns.
class Delivered final : public SendRequest {
public:
  void wait() override {}
};

class LocalComm final : public Comm {
public:
  LocalComm(World& world, int rank) : world_(world), rank_(rank) {}

  int rank() const override { return rank_; }
  int size() const override { return world_.nodes; }
  Topology topology() const override { return world_.topology; }
  double now() const override {
    return std::chrono::duration<double>(Clock::now() - world_.start).count();
  }
  using Comm::isend;

  SendHandle isend(int dst, int tag, Message m) override {
    Mailbox& box = world_.boxes.at(std::size_t(check_rank(dst, "destination")));
    {
      std::lock_guard g(box.lock);
      box.queue.push_back({rank_, tag, std::move(m)});
    }
    box.arrived.notify_all();
    return std::make_unique<Delivered>();
  }

  Message recv_message(int src, int tag, int* from) override {
    if (src != kAnySource) check_rank(src, "source");
    Mailbox& box = world_.boxes[std::size_t(rank_)];
    const auto deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(
                           std::chrono::duration<double>(world_.options.deadlock_after_s));
    std::unique_lock g(box.lock);
    for (;;) {
      for (auto it = box.queue.begin(); it != box.queue.end(); ++it)
        if (it->tag == tag && (src == kAnySource || it->src == src)) {
          Envelope e = std::move(*it);
          box.queue.erase(it);
          if (from) *from = e.src;
          return std::move(e.message);
        }
      if (world_.failed) throw std::runtime_error(where(src, tag) + ": another rank failed");
      if (box.arrived.wait_until(g, deadline) == std::cv_status::timeout)
        throw std::runtime_error(where(src, tag) + ": nothing arrived (a deadlock)");
    }
  }

private:
  int check_rank(int r, const char* what) const {
    const int last = world_.nodes - (world_.options.host ? 0 : 1);
    if (r < 0 || r > last)
      throw std::invalid_argument("local comm: rank " + std::to_string(rank_) + ": " + what + " " +
                                  std::to_string(r) + " is not a rank of the run");
    return r;
  }
  std::string where(int src, int tag) const {
    return "local comm: rank " + std::to_string(rank_) + " receiving tag " + std::to_string(tag) +
           " from " + (src == kAnySource ? "any source" : std::to_string(src));
  }

  World& world_;
  int rank_;
};

} // namespace

void run_local(int nodes, Topology topology, const std::function<void(Comm&)>& rank_main,
               LocalRun options) {
  if (nodes < 1) throw std::invalid_argument("run_local: nodes must be at least 1");
  if (topology == Topology::Cube && !std::has_single_bit(unsigned(nodes)))
    throw std::invalid_argument("run_local: a cube needs a power of two nodes");
  World world(nodes, topology, options);
  std::vector<std::thread> ranks;
  for (int r = 0; r < int(world.boxes.size()); ++r)
    ranks.emplace_back([&world, &rank_main, r] {
      try {
        LocalComm comm(world, r);
        rank_main(comm);
      } catch (...) {
        world.fail(std::current_exception());
      }
    });
  for (auto& t : ranks)
    t.join();
  if (world.failure) std::rethrow_exception(world.failure);
}

} // namespace zc
