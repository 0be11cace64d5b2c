// The flow network: a message crosses SimGrid's shared links (bandwidth sharing) in an actor of
// its own, a courier, reused for its node's next message.
#include "sim/network_model.hpp"

namespace zc {

namespace sg = simgrid::s4u;

namespace {

class FlowNetwork final : public NetworkModel {
public:
  FlowNetwork(const NetworkModelParts& p, std::vector<sg::Host*> hosts, unsigned stack_kib)
      : net_(p.net), wakeups_(p.wakeups), waits_(p.waits), cost_(p.cost), hosts_(std::move(hosts)),
        message_stack_kib_(stack_kib), idle_couriers_(hosts_.size()) {}

  void carry(const TransitPtr& m, double bytes) override;

private:
  // The actor that carries a message across SimGrid's links.
  struct Courier {
    sg::ActorPtr actor;
    TransitPtr job; // the message to carry, null while idle
    double bytes = 0;
  };
  void courier_loop(Courier& c);

  SimNetwork& net_;
  Wakeups& wakeups_;
  RankWaits& waits_;
  SimCost& cost_;
  std::vector<sg::Host*> hosts_;
  unsigned message_stack_kib_;
  std::vector<std::unique_ptr<Courier>> couriers_;
  std::vector<std::vector<Courier*>> idle_couriers_; // by sending rank
};

// A courier runs on a small stack: its code is a few calls deep, and SimGrid's default (8 MiB,
// mapped and unmapped apart) cost the host a mmap, two mprotects, a munmap and fresh pages each. A
// courier that has delivered waits for the next message of its node instead of ending: SimGrid
// clears a new actor's stack (calloc) and unwinds an ending one with an exception, the host cost
// of most messages. It starts at once as a new actor would (SimGrid runs it at this virtual time,
// after the actors already due), on the sender's host.
void FlowNetwork::carry(const TransitPtr& m, double bytes) {
  m->holds.clear();
  auto& idle = idle_couriers_[std::size_t(m->src)];
  if (!idle.empty()) {
    Courier* c = idle.back();
    idle.pop_back();
    c->job = m;
    c->bytes = bytes;
    c->actor->resume();
    return;
  }
  couriers_.push_back(std::make_unique<Courier>());
  Courier* c = couriers_.back().get();
  c->job = m;
  c->bytes = bytes;
  c->actor = sg::Actor::init("msg", hosts_[std::size_t(m->src)])
                 ->set_stacksize(message_stack_kib_)
                 ->start([this, c] { courier_loop(*c); });
  c->actor->daemonize(); // an idle courier does not keep the simulation going
  ++cost_.actors;
}

void FlowNetwork::courier_loop(Courier& c) {
  for (;;) {
    TransitPtr m = std::move(c.job);
    net_.transfer(m->src, m->dst, c.bytes);
    m->arrival = wakeups_.now();
    waits_.arrived(*m);
    idle_couriers_[std::size_t(m->src)].push_back(&c);
    m.reset();
    while (!c.job) {
      ++cost_.actor_switches;
      sg::this_actor::suspend();
    }
  }
}

} // namespace

std::unique_ptr<NetworkModel> flow_network(const NetworkModelParts& p, std::vector<sg::Host*> hosts,
                                           unsigned message_stack_kib) {
  return std::make_unique<FlowNetwork>(p, std::move(hosts), message_stack_kib);
}

} // namespace zc
