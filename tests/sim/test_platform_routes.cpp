// The routes a platform file declares, checked before SimGrid computes any (sim/platform_routes):
// SimGrid's Dijkstra zones looped for ever or crashed on a graph that leaves a host out, a Full
// zone aborted on a missing route, and a zone route with bad gateways aborted the first flow over
// it.
#include <gtest/gtest.h>

#include <string>

#include "sim/platform_routes.hpp"
#include "util/error.hpp"

namespace zc {
namespace {

// Three hosts joined by one-way routes a -> b -> c -> a (a cycle: every host reaches every other)
// in a zone of `routing`, plus the routes `extra` and a host zone linked both ways.
std::string platform(
    const std::string& routing, const std::string& routes,
    const std::string& zone_routes =
        R"(<zoneRoute src="n" dst="h" gw_src="a" gw_dst="srm" symmetrical="NO"><link_ctn id="up"/></zoneRoute>
<zoneRoute src="h" dst="n" gw_src="srm" gw_dst="a" symmetrical="NO"><link_ctn id="down"/></zoneRoute>)") {
  return R"(<?xml version='1.0'?><platform version="4.1"><zone id="m" routing="Full">
<zone id="n" routing=")" +
         routing + R"("><host id="a" speed="1Mf"/><host id="b" speed="1Mf"/>
<host id="c" speed="1Mf"/><link id="l" bandwidth="1MBps" latency="0s"/>
)" + routes +
         R"(</zone>
<zone id="h" routing="None"><host id="srm" speed="1Mf"/></zone>
<link id="up" bandwidth="1MBps" latency="0s"/><link id="down" bandwidth="1MBps" latency="0s"/>
)" + zone_routes +
         "</zone></platform>";
}

std::string route(const std::string& a, const std::string& b, bool symmetrical = false) {
  return "<route src=\"" + a + "\" dst=\"" + b + "\" symmetrical=\"" +
         (symmetrical ? "YES" : "NO") + "\"><link_ctn id=\"l\"/></route>\n";
}

std::string refusal(const std::string& xml) {
  try {
    check_declared_routes(xml, "p.xml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string cycle = route("a", "b") + route("b", "c") + route("c", "a");

TEST(PlatformRoutes, ConnectedGraphsAndCompleteFullZonesPass) {
  for (const char* r : {"Dijkstra", "DijkstraCache", "Floyd"})
    EXPECT_EQ(refusal(platform(r, cycle)), "") << r;
  EXPECT_EQ(refusal(platform("Full", route("a", "b", true) + route("b", "c", true) +
                                         route("a", "c", true))),
            "");
}

TEST(PlatformRoutes, AHostLeftOutIsNamedInBothDirections) {
  // b -> c removed: c is reached from nobody.
  const std::string no_into_c = route("a", "b") + route("c", "a");
  EXPECT_NE(refusal(platform("DijkstraCache", no_into_c)).find("no route from 'b' to 'a'"),
            std::string::npos); // b reaches neither c nor a
  // c -> a removed: a cannot be reached back.
  const std::string no_back = route("a", "b") + route("b", "c");
  EXPECT_NE(refusal(platform("Dijkstra", no_back)).find("to 'a'"), std::string::npos);
  // Every route of a host removed (the Volvox ring without node3's routes).
  EXPECT_NE(refusal(platform("Floyd", route("a", "b", true))).find("'c'"), std::string::npos);
}

TEST(PlatformRoutes, AFullZoneNeedsEveryOrderedPair) {
  const std::string one_way = route("a", "b", true) + route("b", "c", true) + route("a", "c");
  EXPECT_NE(refusal(platform("Full", one_way)).find("no route from 'c' to 'a'"), std::string::npos);
}

TEST(PlatformRoutes, ZoneRoutesJoinTheZonesBothWaysThroughTheirOwnHosts) {
  const std::string up_only =
      R"(<zoneRoute src="n" dst="h" gw_src="a" gw_dst="srm" symmetrical="NO"><link_ctn id="up"/></zoneRoute>)";
  EXPECT_NE(refusal(platform("Dijkstra", cycle, up_only)).find("no route from 'h' to 'n'"),
            std::string::npos);
  const std::string bad_gateway =
      R"(<zoneRoute src="n" dst="h" gw_src="srm" gw_dst="srm"><link_ctn id="up"/></zoneRoute>
<zoneRoute src="h" dst="n" gw_src="srm" gw_dst="a"><link_ctn id="down"/></zoneRoute>)";
  EXPECT_NE(refusal(platform("Dijkstra", cycle, bad_gateway)).find("gw_src=\"srm\""),
            std::string::npos);
}

TEST(PlatformRoutes, ARouteGivenTwiceIsRefused) {
  // SimGrid ended the process on each of these (a crash in sg_platf_new_route, an assertion).
  for (const std::string& routes :
       {cycle + route("a", "b"),
        route("a", "b", true) + route("b", "a") + route("b", "c", true) + route("c", "a", true)}) {
    SCOPED_TRACE(routes);
    EXPECT_NE(refusal(platform("Full", routes)).find("is declared twice"), std::string::npos)
        << refusal(platform("Full", routes));
  }
  const std::string symmetrical_zone_routes =
      R"(<zoneRoute src="n" dst="h" gw_src="a" gw_dst="srm"><link_ctn id="up"/></zoneRoute>
<zoneRoute src="h" dst="n" gw_src="srm" gw_dst="a"><link_ctn id="down"/></zoneRoute>)";
  EXPECT_NE(
      refusal(platform("Dijkstra", cycle, symmetrical_zone_routes)).find("h -> n is declared"),
      std::string::npos);
}

TEST(PlatformRoutes, RoutesJoinPointsOfTheirZoneOverDeclaredLinks) {
  EXPECT_NE(refusal(platform("Dijkstra", cycle + route("a", "x"))).find("'x' is not a host"),
            std::string::npos);
  std::string unknown = route("a", "b");
  unknown.replace(unknown.find("id=\"l\""), 6, "id=\"nope\"");
  EXPECT_NE(refusal(platform("Dijkstra", unknown + route("b", "c") + route("c", "a")))
                .find("no link 'nope'"),
            std::string::npos);
}

TEST(PlatformRoutes, CommentedOutRoutesDoNotCount) {
  const std::string commented =
      route("a", "b") + "<!-- " + route("b", "c") + " -->" + route("c", "a");
  EXPECT_NE(refusal(platform("Dijkstra", commented)), "");
}

} // namespace
} // namespace zc
