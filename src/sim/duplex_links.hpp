#pragma once
// Links whose two directions slow each other down, for the fidelities whose times zcube computes
// (analytic, circuit). A T800 link moves 1.7 MB/s one way, but each data byte needs an acknowledge
// in the other direction, so with both directions busy it moves 2.35 MB/s in all
// (docs/machines.md): a direction's bytes go at the one-way rate while the reverse direction is
// idle and at half the two-way total while it also carries data. A transfer crossing several links
// (a circuit) goes at its slowest link's rate. Transfers in the same direction do not slow each
// other here: under circuit a channel has one owner at a time, and analytic has no contention. The
// flow fidelity gets the same rule from SimGrid: a shared link of the two-way total under each pair
// of directions (machine/platform_xml.cpp).
#include <cstdint>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include "machine/machine.hpp"
#include "sim/transit.hpp"

namespace zc {

class DuplexLinks {
public:
  explicit DuplexLinks(const NetworkParams& net)
      : one_way_(net.per_byte_s), both_busy_(net.both_busy_per_byte_s()) {}

  // A transfer whose end time changed (or was set): it ends at `end` unless a later change with a
  // higher version supersedes it.
  struct Change {
    TransitPtr m;
    double end;
    std::uint64_t version;
  };
  // m's bytes start crossing the directed `links` at time t.
  void begin(const TransitPtr& m, const std::vector<std::pair<int, int>>& links, double bytes,
             double t, std::vector<Change>& out);
  // m's bytes have all crossed at time t.
  void end(const Transit& m, double t, std::vector<Change>& out);
  // True when `version` is m's latest end.
  bool current(const Transit& m, std::uint64_t version) const;

private:
  using Link = std::pair<int, int>;
  struct Flow {
    TransitPtr m;
    std::vector<Link> links;
    double remaining = 0; // bytes not yet across at `since`
    double per_byte = 0;  // seconds a byte since `since`
    double since = 0;
    std::uint64_t version = 0;
  };
  double per_byte(const std::vector<Link>& links) const;
  // The flows on the reverse directions of `links`, whose rate may have changed at t.
  void rerate_reverse(const std::vector<Link>& links, double t, std::uint64_t skip,
                      std::vector<Change>& out);

  double one_way_, both_busy_;
  std::uint64_t next_id_ = 0;
  // Versions are unique over all flows: a stale end of a message's previous hop never matches the
  // flow of its next hop.
  std::uint64_t last_version_ = 0;
  std::map<std::uint64_t, Flow> flows_;                  // by start order: deterministic re-rating
  std::unordered_map<const Transit*, std::uint64_t> id_; // a message has one flow at a time
  std::map<Link, std::vector<std::uint64_t>> busy_;      // directed link -> its flows
};

} // namespace zc
