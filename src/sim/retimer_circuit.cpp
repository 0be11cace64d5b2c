// The retimer's circuit switching (retimer.hpp): Delivery's channel bookkeeping
// (sim/network_circuit.cpp), without SimGrid: a message's holds acquire their channels one by one,
// each granted first come, first served, and released at the hold's end.
#include "sim/retimer.hpp"

namespace zc::retiming {

std::uint32_t Retimer::channel_id(std::pair<int, int> c) {
  const std::uint64_t key = (std::uint64_t(std::uint32_t(c.first)) << 32) | std::uint32_t(c.second);
  auto [it, fresh] = channel_ids_.try_emplace(key, std::uint32_t(channels_.size()));
  if (fresh) channels_.emplace_back();
  return it->second;
}

void Retimer::schedule_release(std::uint32_t id) {
  Channel& c = channels_[id];
  if (c.queue.empty() || c.free_at == kUnknown || c.release_pending) return;
  c.release_pending = true;
  schedule_net(c.free_at, Event::Net::Release, nullptr, id);
}

void Retimer::hand_over(std::uint32_t id, std::vector<Msg*>& woken) {
  Channel& c = channels_[id];
  if (c.queue.empty()) {
    c.owner = nullptr;
    return;
  }
  Msg* w = c.queue.front();
  c.queue.pop_front();
  c.owner = w;
  c.free_at = kUnknown;
  ++w->next_channel;
  woken.push_back(w);
}

void Retimer::advance(Msg* m, double t) {
  if (m->holds.empty()) {
    m->arrival = t;
    arrived(*m);
    return;
  }
  for (;;) {
    const Hold& h = m->holds[m->stage];
    while (m->next_channel < h.ids.size()) {
      const std::uint32_t id = h.ids[m->next_channel];
      Channel& c = channels_[id];
      if (c.owner && !(c.free_at <= t && c.queue.empty())) {
        c.queue.push_back(m);
        schedule_release(id);
        return;
      }
      c.owner = m;
      c.free_at = kUnknown;
      ++m->next_channel;
    }
    const double end = t + h.seconds;
    if (!end_hold(m, end)) return;
    t = end;
  }
}

bool Retimer::end_hold(Msg* m, double end) {
  const Hold& h = m->holds[m->stage];
  for (const std::uint32_t id : h.ids) {
    channels_[id].free_at = end;
    schedule_release(id);
  }
  if (m->stage + 1 == m->holds.size()) {
    m->arrival = end;
    arrived(*m);
    return false;
  }
  ++m->stage;
  m->next_channel = 0;
  if (!h.channels.empty() || !m->holds[m->stage].channels.empty()) {
    schedule_net(end, Event::Net::NextStage, m, 0);
    return false;
  }
  return true;
}

void Retimer::process(const Event& e) {
  std::vector<Msg*> woken;
  if (e.net == Event::Net::NextStage) {
    const auto& prev = e.m->holds[e.m->stage - 1].ids;
    for (auto it = prev.rbegin(); it != prev.rend(); ++it)
      if (channels_[*it].owner == e.m) hand_over(*it, woken);
    advance(e.m, e.time);
  } else {
    Channel& c = channels_[e.channel];
    c.release_pending = false;
    if (c.owner && c.free_at <= e.time)
      hand_over(e.channel, woken);
    else
      schedule_release(e.channel);
  }
  for (Msg* w : woken)
    advance(w, e.time);
}

} // namespace zc::retiming
