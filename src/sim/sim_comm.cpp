#include "sim/sim_comm.hpp"

#include <stdexcept>

namespace zc {

namespace sg = simgrid::s4u;

namespace {
class SimSendRequest final : public SendRequest {
public:
  SimSendRequest(Delivery& d, int self, TransitPtr m, NodeStats& s)
      : delivery_(d), self_(self), msg_(std::move(m)), stats_(s) {}
  void wait() override {
    if (!msg_) return;
    const double t0 = sg::Engine::get_clock();
    delivery_.await_arrival(self_, *msg_);
    msg_ = nullptr;
    const double t1 = sg::Engine::get_clock();
    stats_.comm_s += t1 - t0;
    if (stats_.log) stats_.log->activity(Activity::Send, t0, t1);
  }
  ~SimSendRequest() override {
    if (msg_)
      delivery_.await_arrival(self_, *msg_); // an unwaited send completes before its handle dies
  }

private:
  Delivery& delivery_;
  int self_;
  TransitPtr msg_;
  NodeStats& stats_;
};
} // namespace

void SimComm::check_rank(int r, const char* what) const {
  if (r < 0 || r > size())
    throw std::out_of_range(std::string(what) + ": rank " + std::to_string(r) + " out of 0.." +
                            std::to_string(size()));
}

SendHandle SimComm::isend(int dst, int tag, Message msg) {
  check_rank(dst, "send");
  stats_.count_send(msg.payload.size(), msg.charged);
  if (stats_.log)
    stats_.log->sends.push_back(
        {dst, tag, msg.charged, message_hops(topology_, nodes_, rank_, dst), now()});
  return std::make_unique<SimSendRequest>(delivery_, rank_,
                                          delivery_.post(rank_, dst, tag, std::move(msg)), stats_);
}

Message SimComm::recv_message(int src, int tag, int* from) {
  if (src != kAnySource) check_rank(src, "recv");
  const double t0 = sg::Engine::get_clock();
  TransitPtr m = delivery_.receive(rank_, src, tag);
  if (from) *from = m->src;
  const double t1 = sg::Engine::get_clock();
  stats_.comm_s += t1 - t0;
  if (stats_.log) {
    stats_.log->activity(Activity::Wait, t0, t1);
    stats_.log->recvs.push_back({m->src, m->tag, m->arrival, t1});
  }
  return {std::move(m->data), m->charged};
}

} // namespace zc
