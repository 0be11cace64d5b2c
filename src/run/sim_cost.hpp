#pragma once
// What a simulation cost the simulator, counted in its own events rather than in host seconds:
// the same numbers in every run of the same configuration, on any host (the report's
// "simulation_cost"; the host's seconds are in its "host" section and in bench/). The network
// fidelities differ mostly here: analytic computes each arrival when the message is sent, circuit
// adds zcube's channel events and the actor that processes them, flow hands every message to
// SimGrid's bandwidth sharing in an actor of its own.
#include <cstdint>

#include <nlohmann/json.hpp>

namespace zc {

struct SimCost {
  // Times SimGrid's engine advanced its clock (its on_time_advance signal): the distinct dates the
  // simulation went through, each a solve of SimGrid's models.
  std::uint64_t time_steps = 0;
  // Times one of zcube's actors (a rank, the network's actor, a message's courier) gave the CPU
  // back to SimGrid and was later resumed: a suspended wait, a SimGrid sleep or transfer. Each is
  // a pair of context switches.
  std::uint64_t actor_switches = 0;
  // Actors started: the ranks, the network's actor (circuit, and analytic on half-duplex-limited
  // links), the couriers (flow).
  std::uint64_t actors = 0;
  // SimGrid timers set by zcube's wake-ups (one per distinct wake-up date).
  std::uint64_t timers = 0;
  // zcube's own network events: a contended channel's release and a message's next stage
  // (circuit), the start and end of a hop's bytes on half-duplex-limited links.
  std::uint64_t network_events = 0;
  // Transfers whose bandwidth SimGrid's network model shares (the flow fidelity's messages, one
  // per hop on store-and-forward links and per host-link leg).
  std::uint64_t flows = 0;
};

inline void to_json(nlohmann::json& j, const SimCost& c) {
  j = {{"time_steps", c.time_steps}, {"actor_switches", c.actor_switches}, {"actors", c.actors},
       {"timers", c.timers},         {"network_events", c.network_events}, {"flows", c.flows}};
}

} // namespace zc
