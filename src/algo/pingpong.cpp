#include "algo/pingpong.hpp"

#include <sstream>

#include "machine/topology.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

std::vector<std::size_t> parse_sizes(const std::string& s) {
  std::vector<std::size_t> v;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');) {
    if (item.empty() || item.find_first_not_of("0123456789") != std::string::npos)
      throw UsageError("--sizes '" + s + "': expected comma-separated byte counts");
    v.push_back(std::stoull(item));
  }
  return v;
}

void pingpong_node(NodeContext& ctx) {
  Comm& c = ctx.comm();
  const int P = c.size();
  const int from = std::stoi(ctx.options().get("from"));
  const std::string to_opt = ctx.options().get("to");
  const auto sizes = parse_sizes(ctx.options().get("sizes"));
  std::vector<int> targets;
  if (to_opt.empty()) {
    for (int t = 0; t < P; ++t)
      if (t != from) targets.push_back(t);
  } else {
    for (auto t : parse_sizes(to_opt))
      targets.push_back(int(t));
  }
  for (int t : targets)
    if (from < 0 || from >= P || t < 0 || t >= P || t == from)
      throw UsageError("--from/--to must name two different nodes of 0.." + std::to_string(P - 1));
  auto results = nlohmann::json::array();
  for (int t : targets)
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
  if (c.rank() == 0 && from != 0) {
    // Node 0's metrics feed the report: fetch them from `from`.
    ctx.metrics()["results"] = nlohmann::json::parse([&] {
      Bytes b = c.recv(from, 3);
      return std::string(b.begin(), b.end());
    }());
  } else if (c.rank() == from && from != 0) {
    const std::string s = results.dump();
    c.send(0, 3, Bytes(s.begin(), s.end()));
  }
}

} // namespace

Algorithm pingpong_algorithm() {
  Algorithm a;
  a.name = "pingpong";
  a.summary = "communication benchmark: one-way time per message size and distance";
  a.node = pingpong_node;
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
                "0,64,100,101,1024,65536",
                {},
                0,
                1LL << 30,
                "message sizes in bytes, comma-separated"}};
  return a;
}

} // namespace zc
