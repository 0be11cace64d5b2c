#include "algo/tools/pingpong.hpp"

#include <sstream>

#include <nlohmann/json.hpp>

#include "machine/topology.hpp"
#include "machine/units.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

// Sizes and node lists were checked by validate_options (whole bytes with units, node numbers).
std::vector<std::size_t> parse_sizes(const std::string& s) {
  std::vector<std::size_t> v;
  for (double b : parse_bytes_list(s, "--sizes"))
    v.push_back(std::size_t(b));
  return v;
}

std::vector<int> parse_nodes(const std::string& s) {
  std::vector<int> v;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');)
    v.push_back(std::stoi(item));
  return v;
}

// The answering nodes: --to, else every node but --from.
std::vector<int> targets(const AlgorithmOptions& o, int P) {
  const int from = std::stoi(o.get("from"));
  if (!o.get("to").empty()) return parse_nodes(o.get("to"));
  std::vector<int> t;
  for (int n = 0; n < P; ++n)
    if (n != from) t.push_back(n);
  return t;
}

void check_nodes(const AlgorithmOptions& o, int P) {
  const int from = std::stoi(o.get("from"));
  if (from >= P)
    throw UsageError("--from " + o.get("from") + ": no such node (the machine has nodes 0.." +
                     std::to_string(P - 1) + ")");
  for (int t : targets(o, P))
    if (t >= P || t == from)
      throw UsageError(
          "--to " + std::to_string(t) + ": " +
          (t == from ? std::string("the sending node itself")
                     : "no such node (the machine has nodes 0.." + std::to_string(P - 1) + ")"));
  if (targets(o, P).empty())
    throw UsageError("--from " + o.get("from") + ": no other node to answer");
}

void pingpong_node(NodeContext& ctx) {
  Comm& c = ctx.comm();
  const int P = c.size();
  const int from = std::stoi(ctx.options().get("from"));
  const auto sizes = parse_sizes(ctx.options().get("sizes"));
  auto results = nlohmann::json::array();
  for (int t : targets(ctx.options(), P))
    for (std::size_t m : sizes) {
      if (c.rank() == from) {
        const double t0 = c.now();
        c.send(t, 1, Bytes(m, 0x5a));
        Bytes back = c.recv(t, 2);
        const double rtt = c.now() - t0;
        results.push_back({{"bytes", m},
                           {"from", from},
                           {"to", t},
                           {"hops", hops(c.topology(), P, from, t)},
                           {"one_way_s", rtt / 2},
                           {"round_trip_s", rtt}});
      } else if (c.rank() == t) {
        Bytes b = c.recv(from, 1);
        c.send(from, 2, std::move(b));
      }
    }
  if (c.rank() == from) ctx.metrics()["results"] = results;
}

} // namespace

Algorithm pingpong_algorithm() {
  Algorithm a;
  a.name = "pingpong";
  a.summary = "communication benchmark: one-way time per message size and distance";
  a.node = pingpong_node;
  a.draws_picture = false;
  a.check_nodes = check_nodes;
  // The sending node measured: its results are the run's.
  a.metrics_node = [](const AlgorithmOptions& o) { return std::stoi(o.get("from")); };
  a.options = {{"from", OptionSpec::Kind::Integer, "0", {}, 0, 1023, "sending node"},
               {"to",
                OptionSpec::Kind::NodeList,
                "",
                {},
                0,
                1023,
                "answering node(s), comma-separated (default: every other node)"},
               {"sizes",
                OptionSpec::Kind::SizeList,
                "0B,64B,100B,101B,1KiB,64KiB",
                {},
                0,
                1LL << 30,
                "message sizes with units, comma-separated"}};
  return a;
}

} // namespace zc
