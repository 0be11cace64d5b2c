#include "algo/blazek/blazek_methods.hpp"

namespace zc {

std::vector<Algorithm> blazek_algorithms() {
  auto make = [](const char* name, const char* summary, auto host, auto node,
                 std::vector<OptionSpec> options) {
    Algorithm a;
    a.name = name;
    a.summary = summary;
    a.uses_host = true;
    a.host = host;
    a.node = node;
    a.options = std::move(options);
    a.untextured = true; // Blazek's renderer had no textures
    // Ch. VI: "the time a task takes on one processor", the thesis's Algorithm 3 (docs/papers.md).
    a.reference = "node-initiated";
    return a;
  };
  return {make("host-initiated",
               "Blazek 1991: host tessellates, polygon packets, hierarchical merge",
               blazek::host_initiated_host, blazek::host_initiated_node,
               // Ch. V: "Polygon packet sizes ranging from 10 through 10^3 polygons per packet".
               {{"packet",
                 OptionSpec::Kind::Integer,
                 "100",
                 {},
                 10,
                 1000,
                 "polygons per packet from the host"}}),
          make("node-initiated", "Blazek 1991: descriptions to nodes, node tessellation, merge",
               blazek::describe_round_robin, blazek::node_initiated_node, {}),
          make("object-forwarding", "Blazek 1991: node strips, objects forwarded to strip owners",
               blazek::describe_round_robin, blazek::object_forwarding_node,
               {{"forward",
                 OptionSpec::Kind::Choice,
                 "object",
                 {"object", "polygons"},
                 0,
                 0,
                 "what a node forwards to strip owners: the description or its polygons"}}),
          make("host-broadcast", "Blazek 1991: every object to every node, strips or interleaved",
               blazek::host_broadcast_host, blazek::host_broadcast_node,
               {{"lines",
                 OptionSpec::Kind::Choice,
                 "strips",
                 {"strips", "interleaved"},
                 0,
                 0,
                 "rows per node: contiguous strips or interleaved lines"}})};
}

} // namespace zc
