#pragma once
// The routes a platform file declares, checked before SimGrid computes any: SimGrid's Dijkstra
// zones loop for ever or crash on a graph that does not connect every host, a Full zone aborts on
// a missing route, and a zone route with bad gateways aborts the first flow that takes it. Every
// host of a zone with explicit routes must reach every other one, and every zone route must join
// hosts of the zones it names, in both directions.
#include <string>

namespace zc {

// InputError naming `label` and the pair of hosts (or zones) without a route.
void check_declared_routes(const std::string& xml, const std::string& label);

} // namespace zc
