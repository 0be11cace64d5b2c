#pragma once
// The retimer of retime() (retime.hpp): a discrete-event simulation of one draw over a recorded
// run's calls, in this process. Its ranks' calls and waits are in retimer.cpp, circuit
// switching's channels in retimer_circuit.cpp.
#include <cstdint>
#include <deque>
#include <limits>
#include <queue>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "comm/comm.hpp"
#include "run/sim_cost.hpp"
#include "sim/retime.hpp"
#include "sim/sim_network.hpp"

namespace zc::retiming {

constexpr double kUnknown = std::numeric_limits<double>::infinity();

struct Msg {
  int src = 0, dst = 0, tag = 0;
  double sent_at = 0, arrival = kUnknown;
  std::vector<Hold> holds;
  std::size_t stage = 0, next_channel = 0;
};

// Delivery's channel bookkeeping (sim/network_circuit.cpp), without SimGrid.
struct Channel {
  const Msg* owner = nullptr;
  double free_at = 0;
  std::deque<Msg*> queue;
  bool release_pending = false;
};

struct Rank {
  std::size_t pc = 0;
  bool done = false;
  enum class Wait { None, Arrival, Recv } wait = Wait::None;
  const Msg* awaited = nullptr;
  int recv_src = 0, recv_tag = 0;
  double deadline = kUnknown; // its pending wake-up
  std::uint64_t generation = 0;
  std::vector<std::pair<std::uint32_t, double>> open; // phase (string id), its start
  std::vector<double> totals;                         // by string id
  std::vector<char> entered;                          // by string id
  std::vector<std::uint32_t> order;                   // phases in the order first entered
  std::vector<Msg*> handles;
  double memory = 0, capacity = 0;
  double timed_start = 0, timed_end = 0, finish = 0;
  bool timed = false, timed_ended = false;
};

struct Event {
  double time;
  int order;         // ranks in rank order, the network after them
  std::uint64_t seq; // then first scheduled first
  int rank;          // -1: a network event
  enum class Net { NextStage, Release } net = Net::Release;
  Msg* m = nullptr;
  std::uint32_t channel = 0;
  std::uint64_t generation = 0;
  bool operator>(const Event& o) const {
    if (time != o.time) return time > o.time;
    if (order != o.order) return order > o.order;
    return seq > o.seq;
  }
};

class Retimer {
public:
  Retimer(const CallTrace& t, const RetimeMachine& m, const ModelDraw& d);
  // The trace under the draw: every rank resumed in turn, the network's events among them.
  RetimedRun run();

private:
  // A wake-up as Wakeups dates it: a wait of `seconds` from now, at least the precision.
  double after(double seconds) const {
    return seconds > 0 ? now_ + std::max(seconds, m_.precision) : now_;
  }
  void schedule_rank(int r, double time) {
    Rank& k = ranks_[std::size_t(r)];
    k.deadline = time;
    events_.push({time, r, seq_++, r, Event::Net::Release, nullptr, 0, ++k.generation});
  }
  void schedule_net(double time, Event::Net kind, Msg* m, std::uint32_t channel) {
    net_events_.push({time, int(ranks_.size()) + 1, seq_++, -1, kind, m, channel, 0});
  }

  void diverge(RetimedRun::Status s, const std::string& why) {
    result_.status = s;
    result_.why = why;
  }

  void resume(int r);
  bool step(int r, Rank& k, const Call& c);
  bool await(int r, Rank& k, const Msg* m);
  bool receive(int r, Rank& k, const Call& c);
  Msg* post(int r, const Call& c);
  void arrived(Msg& m);
  void charge(Rank& k, const Counters& w, int r);

  // Circuit fidelity.
  std::uint32_t channel_id(std::pair<int, int> c);
  void advance(Msg* m, double t);
  bool end_hold(Msg* m, double end);
  void schedule_release(std::uint32_t id);
  void hand_over(std::uint32_t id, std::vector<Msg*>& woken);
  void process(const Event& e);

  void finish();

  const CallTrace& t_;
  const RetimeMachine& m_;
  NetworkParams net_params_;
  SimCost unused_cost_; // the simulator's own event counts: none here
  SimNetwork net_;
  bool circuit_;
  std::vector<CostTable> cost_;
  std::vector<double> phase_factor_;
  double no_phase_factor_ = 1;
  std::vector<Rank> ranks_;
  std::vector<std::vector<Msg*>> inbox_; // by destination, pending in send order
  std::vector<char> seen_;               // receive()'s scratch: sources met
  std::deque<Msg> msgs_;
  std::unordered_map<std::uint64_t, std::uint32_t> channel_ids_; // (from, to) -> index
  std::vector<Channel> channels_;
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> events_;     // ranks
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> net_events_; // network
  std::uint64_t seq_ = 0;
  double now_ = 0;
  RetimedRun result_;
};

} // namespace zc::retiming
