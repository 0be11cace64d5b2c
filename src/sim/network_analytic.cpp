// The analytic network: a message's arrival is the sum of its holds' times from its sending, known
// at once (no contention); the receiver, if it waits for it, wakes then.
#include "sim/network_model.hpp"

namespace zc {

namespace {

class AnalyticNetwork final : public NetworkModel {
public:
  explicit AnalyticNetwork(const NetworkModelParts& p) : net_(p.net), waits_(p.waits) {}

  void carry(const TransitPtr& m, double bytes) override {
    double t = m->sent_at;
    net_.holds(m->src, m->dst, bytes, m->holds);
    for (const Hold& h : m->holds)
      t += h.seconds;
    m->arrival = t;
    // The sender is running (it posts this): only the destination may be waiting.
    waits_.notify(waits_[m->dst], *m);
  }

private:
  SimNetwork& net_;
  RankWaits& waits_;
};

} // namespace

std::unique_ptr<NetworkModel> analytic_network(const NetworkModelParts& p) {
  return std::make_unique<AnalyticNetwork>(p);
}

} // namespace zc
