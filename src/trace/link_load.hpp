#pragma once
// Messages in flight on each directed channel over time, from the messages' routes (e-cube on the
// cube, shortest way on the ring; the host computer's link to node 0): a message occupies every
// channel of its route from its send to its arrival.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "trace/timeline.hpp"

namespace zc {

using Link = std::pair<int, int>; // (from, to); the host computer is rank P
// Per link the steps (time, messages in flight from then on), in time order.
std::map<Link, std::vector<std::pair<double, int>>> link_load(const Timeline& tl,
                                                              const std::string& topology);
// "link 0->4", or the host computer's links (rank P) by their platform names: "host-up (node
// 0->srm)".
std::string link_name(const Link& l, int P);

} // namespace zc
