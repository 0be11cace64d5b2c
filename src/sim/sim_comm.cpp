#include "sim/sim_comm.hpp"

#include <stdexcept>

namespace zc {

namespace sg = simgrid::s4u;

namespace {
class ActorRequest final : public SendRequest {
public:
  ActorRequest(sg::ActorPtr a, NodeStats& s) : actor_(std::move(a)), stats_(s) {}
  void wait() override {
    if (!actor_) return;
    const double t0 = sg::Engine::get_clock();
    actor_->join();
    actor_ = nullptr;
    stats_.comm_s += sg::Engine::get_clock() - t0;
  }
  ~ActorRequest() override {
    if (actor_) actor_->join(); // an unwaited send still completes before its handle dies
  }

private:
  sg::ActorPtr actor_;
  NodeStats& stats_;
};
} // namespace

SimComm::SimComm(int rank, SimNetwork& net, NodeStats& stats)
    : rank_(rank), net_(net), stats_(stats) {}

void SimComm::attach() {
  mbox_ = sg::Mailbox::by_name(mailbox_name(rank_));
  mbox_->set_receiver(sg::Actor::self());
}

void SimComm::check_rank(int r, const char* what) const {
  if (r < 0 || r > size())
    throw std::out_of_range(std::string(what) + ": rank " + std::to_string(r) + " out of 0.." +
                            std::to_string(size()));
}

SendHandle SimComm::isend(int dst, int tag, Bytes data) {
  check_rank(dst, "send");
  auto* msg = new Message{rank_, tag, next_send_[{dst, tag}]++, std::move(data)};
  const double bytes = double(msg->data.size());
  stats_.bytes_sent += msg->data.size();
  stats_.messages += 1;
  SimNetwork* net = &net_;
  const int src = rank_;
  auto actor = sg::Actor::create("msg", sg::this_actor::get_host(), [net, src, dst, msg, bytes]() {
    net->transfer(src, dst, bytes);
    // Delivery: an eager mailbox takes the payload at once (zero simulated bytes: the transfer
    // time has been spent above).
    sg::Mailbox::by_name(mailbox_name(dst))->put_init(msg, 0)->detach();
  });
  return std::make_unique<ActorRequest>(actor, stats_);
}

void SimComm::send(int dst, int tag, Bytes data) {
  isend(dst, tag, std::move(data))->wait();
}

Bytes SimComm::recv(int src, int tag, int* from) {
  if (src != kAnySource) check_rank(src, "recv");
  const double t0 = sg::Engine::get_clock();
  for (;;) {
    for (auto it = stash_.begin(); it != stash_.end(); ++it) {
      Message* m = *it;
      if (m->tag != tag || (src != kAnySource && m->src != src)) continue;
      auto& expect = next_recv_[{m->src, m->tag}];
      if (m->seq != expect) continue;
      ++expect;
      stash_.erase(it);
      Bytes data = std::move(m->data);
      if (from) *from = m->src;
      delete m;
      stats_.comm_s += sg::Engine::get_clock() - t0;
      return data;
    }
    stash_.push_back(mbox_->get<Message>());
  }
}

} // namespace zc
