#include "sim/sim_network.hpp"

#include <algorithm>

#include "util/error.hpp"

namespace zc {

namespace sg = simgrid::s4u;

SimNetwork::SimNetwork(const NetworkParams& params, Topology topo, int nodes, Fidelity fidelity,
                       std::vector<sg::Host*> hosts, SimCost& cost)
    : p_(params), topo_(topo), nodes_(nodes), fid_(fidelity), hosts_(std::move(hosts)),
      cost_(cost) {}

// A SimGrid sleep of the calling actor (counted as its switch to SimGrid and back).
void SimNetwork::sleep(double seconds) {
  ++cost_.actor_switches;
  sg::this_actor::sleep_for(seconds);
}

sg::MutexPtr SimNetwork::channel(int a, int b) {
  auto& m = channels_[{a, b}];
  if (!m) m = sg::Mutex::create();
  return m;
}

// Occupies `channels` for `seconds` of fixed cost; under the flow model, `flow_bytes` then cross
// the route from flow_src to flow_dst through SimGrid's shared links.
void SimNetwork::hold(const std::vector<std::pair<int, int>>& chans, double seconds,
                      double flow_bytes, int flow_src, int flow_dst) {
  if (fid_ == Fidelity::Flow) {
    if (seconds > 0) sleep(seconds);
    if (flow_bytes > 0) {
      ++cost_.flows;
      ++cost_.actor_switches;
      sg::Comm::sendto(hosts_[flow_src], hosts_[flow_dst], std::uint64_t(flow_bytes));
    }
    return;
  }
  if (fid_ == Fidelity::Analytic || chans.empty()) {
    if (seconds > 0) sleep(seconds);
    return;
  }
  // Circuit: acquire every channel of the path in one global order (dimension order on the
  // cube, which is the e-cube path order), hold them for the whole transfer, release.
  std::vector<std::pair<int, int>> order = chans;
  if (topo_ == Topology::Cube) {
    std::stable_sort(order.begin(), order.end(), [](auto x, auto y) {
      const int dx = x.first ^ x.second, dy = y.first ^ y.second;
      return dx != dy ? dx < dy : x < y;
    });
  } else {
    std::sort(order.begin(), order.end());
  }
  std::vector<sg::MutexPtr> held;
  for (auto c : order) {
    held.push_back(channel(c.first, c.second));
    held.back()->lock();
  }
  if (seconds > 0) sleep(seconds);
  for (auto it = held.rbegin(); it != held.rend(); ++it)
    (*it)->unlock();
}

void SimNetwork::node_transfer(int src, int dst, double m) {
  if (src == dst) return;
  const auto path = route(topo_, nodes_, src, dst);
  const int h = int(path.size());
  if (p_.switching == Switching::StoreAndForward) {
    // Each intermediate node receives the whole message before forwarding it.
    for (auto c : path) {
      const bool flow = fid_ == Fidelity::Flow;
      hold({c}, flow ? p_.startup(m) : p_.startup(m) + m * p_.per_byte_s, m, c.first, c.second);
    }
    return;
  }
  const double fixed = p_.startup(m) + (h - 1) * p_.per_hop_s;
  if (fid_ == Fidelity::Flow)
    hold(path, fixed, m, src, dst);
  else
    hold(path, fixed + m * p_.per_byte_s, 0, src, dst);
}

void SimNetwork::transfer(int src, int dst, double m) {
  const int host = nodes_;
  if (src == host || dst == host) {
    // Host link (srm <-> node 0), then the machine's network to or from node 0.
    if (dst == host) node_transfer(src, 0, m);
    const std::pair<int, int> link = src == host ? std::pair{host, 0} : std::pair{0, host};
    const double t = p_.host_startup_s + (fid_ == Fidelity::Flow ? 0 : m * p_.host_per_byte_s);
    hold({link}, t, fid_ == Fidelity::Flow ? m : 0, link.first, link.second);
    if (src == host) node_transfer(0, dst, m);
    return;
  }
  node_transfer(src, dst, m);
}

namespace {
// Hold n of `out`, made when out has none there yet.
Hold& slot(std::vector<Hold>& out, std::size_t n) {
  if (n == out.size()) out.emplace_back();
  return out[n];
}
} // namespace

// Hold out[n], whose channels are set (node links, or the host link): `fixed` seconds then `bytes`
// over them. Kept (++n) unless it has nothing to wait for and nothing to acquire.
void SimNetwork::finish_hold(std::vector<Hold>& out, std::size_t& n, double fixed, double bytes,
                             bool node_links) const {
  Hold& h = out[n];
  h.seconds = std::max(fixed + bytes * (node_links ? p_.per_byte_s : p_.host_per_byte_s), 0.0);
  h.links.clear();
  h.fixed_s = 0;
  h.bytes = 0;
  if (node_links && bytes > 0 && p_.half_duplex_limited()) {
    h.links.assign(h.channels.begin(), h.channels.end());
    h.fixed_s = std::max(fixed, 0.0);
    h.bytes = bytes;
  }
  auto& chans = h.channels;
  if (fid_ != Fidelity::Circuit) chans.clear();
  if (chans.empty() && h.seconds <= 0) return; // nothing to wait for, nothing to acquire
  // The global order of acquisition (dimension order on the cube: the e-cube path order), which
  // rules out deadlock between circuits. Both orders are total on a path's distinct channels, and
  // an e-cube route already comes in dimension order: sorted only when it is not.
  if (topo_ == Topology::Cube) {
    const auto by_dimension = [](auto x, auto y) {
      const int dx = x.first ^ x.second, dy = y.first ^ y.second;
      return dx != dy ? dx < dy : x < y;
    };
    if (!std::is_sorted(chans.begin(), chans.end(), by_dimension))
      std::sort(chans.begin(), chans.end(), by_dimension);
  } else if (!std::is_sorted(chans.begin(), chans.end())) {
    std::sort(chans.begin(), chans.end());
  }
  ++n;
}

// The same stretches and seconds as node_transfer under the analytic and circuit fidelities.
void SimNetwork::node_holds(int src, int dst, double m, std::vector<Hold>& out,
                            std::size_t& n) const {
  if (src == dst) return;
  if (p_.switching == Switching::StoreAndForward) {
    route_into(topo_, nodes_, src, dst, route_);
    for (auto c : route_) {
      slot(out, n).channels.assign(1, c);
      finish_hold(out, n, p_.startup(m), m, true);
    }
    return;
  }
  auto& path = slot(out, n).channels;
  route_into(topo_, nodes_, src, dst, path);
  const double fixed = p_.startup(m) + (int(path.size()) - 1) * p_.per_hop_s;
  finish_hold(out, n, fixed, m, true);
}

void SimNetwork::holds(int src, int dst, double m, std::vector<Hold>& out) const {
  std::size_t n = 0;
  const int host = nodes_;
  if (src != host && dst != host) {
    node_holds(src, dst, m, out, n);
  } else {
    if (dst == host) node_holds(src, 0, m, out, n);
    slot(out, n).channels.assign(1, src == host ? std::pair{host, 0} : std::pair{0, host});
    finish_hold(out, n, p_.host_startup_s, m, false);
    if (src == host) node_holds(0, dst, m, out, n);
  }
  out.resize(n);
}

} // namespace zc
