#include "sim/delivery.hpp"

#include <algorithm>
#include <limits>

#include <xbt/config.hpp>

namespace zc {

namespace sg = simgrid::s4u;

namespace {

// The model of the run's fidelity: zcube's events (channels, duplex links) under circuit, or
// under analytic on links whose directions slow each other down; else the closed form (analytic)
// or SimGrid's links (flow).
std::unique_ptr<NetworkModel> network_model(const NetworkModelParts& p, Fidelity fidelity,
                                            std::vector<sg::Host*> hosts,
                                            unsigned message_stack_kib) {
  const bool events_driven =
      fidelity == Fidelity::Circuit ||
      (fidelity == Fidelity::Analytic && p.net.params().half_duplex_limited());
  if (events_driven) return circuit_network(p, hosts);
  if (fidelity == Fidelity::Analytic) return analytic_network(p);
  return flow_network(p, std::move(hosts), message_stack_kib);
}

} // namespace

Delivery::Delivery(SimNetwork& net, Fidelity fidelity, std::vector<sg::Host*> hosts,
                   unsigned message_stack_kib, SimCost& cost)
    : wakeups_(simgrid::config::get_value<double>("surf/precision"), cost), ranks_(net.nodes() + 1),
      inboxes_(std::size_t(ranks_), Inbox(ranks_)), waits_(wakeups_, ranks_ + 1) {
  const unsigned stack_kib =
      std::min(message_stack_kib, unsigned(simgrid::config::get_value<int>("contexts/stack-size")));
  model_ = network_model({net, wakeups_, waits_, cost}, fidelity, std::move(hosts), stack_kib);
}

TransitPtr Delivery::post(int src, int dst, int tag, Message&& msg, Blocks&& blocks, bool bundle) {
  TransitPtr m = TransitPtr::make();
  m->src = src;
  m->dst = dst;
  m->tag = tag;
  m->data = std::move(msg.payload);
  m->blocks = std::move(blocks);
  m->bundle = bundle;
  m->charged = msg.charged;
  m->sent_at = wakeups_.now();
  inboxes_[dst].push(m);
  model_->carry(m, double(m->charged));
  return m;
}

void Delivery::compute(int self, double seconds) {
  if (!(seconds > 0)) return;
  Waiter& w = waits_[self];
  wakeups_.set_after(w.sleeper, seconds, 0);
  wakeups_.wait(w.sleeper);
}

void Delivery::await_arrival(int self, const Transit& m, double& now) {
  Waiter& w = waits_[self];
  double reached = kNever;
  while (!(m.arrival <= std::max(now, reached))) {
    if (m.arrival != kNotYet) { // set once: only contention (circuit, flow) leaves it open
      reached = waits_.sleep_until(w, m.arrival, now);
      continue;
    }
    w.send = &m;
    reached = waits_.block(w, m.arrival, now);
    w.send = nullptr;
  }
}

TransitPtr Delivery::receive(int self, int src, int tag, double& now) {
  Waiter& w = waits_[self];
  double reached = kNever;
  for (;;) {
    double wake = kNotYet;
    if (auto m = inboxes_[self].take(src, tag, std::max(now, reached), wake)) return m;
    // From one source, the oldest message of its tag is the one to take (nothing sent later
    // overtakes it): once its arrival is known, sleep until it. From any source, another message
    // may still arrive first.
    if (src != kAnySource && wake != kNotYet) {
      reached = waits_.sleep_until(w, wake, now);
      continue;
    }
    w.receiving = true;
    w.src = src;
    w.tag = tag;
    reached = waits_.block(w, wake, now);
    w.receiving = false;
  }
}

} // namespace zc
