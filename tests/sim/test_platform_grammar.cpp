// sim/platform_grammar: the subset of SimGrid's platform grammar zcube models. Every platform zcube
// writes passes; an element, attribute, value or <config> setting outside it is refused with the
// file, the line and the thing named, before SimGrid sees the file.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "machine/topology.hpp"
#include "sim/platform_grammar.hpp"
#include "util/error.hpp"

namespace zc {
namespace {

// The refusal of `xml` ("" when it passes).
std::string grammar_refusal(const std::string& xml) {
  try {
    check_platform_grammar(xml, "p.xml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string grammar_replaced(std::string x, const std::string& from, const std::string& to) {
  const auto at = x.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) x.replace(at, from.size(), to);
  return x;
}

// The line of the first occurrence of `text` in `xml`.
int grammar_line_of(const std::string& xml, const std::string& text) {
  const auto at = xml.find(text);
  return 1 + int(std::count(xml.begin(), xml.begin() + std::ptrdiff_t(at), '\n'));
}

const std::string grammar_cube = platform_xml(machine_spec("ipsc2"), 4, Topology::Cube);
const std::string grammar_ring = platform_xml(machine_spec("volvox"), 4, Topology::Ring);

TEST(PlatformGrammar, EveryPlatformZcubeWritesPasses) {
  for (const auto& name : machine_names())
    for (Topology t : {Topology::Cube, Topology::Ring})
      for (int p : {1, 2, 8, 64}) {
        SCOPED_TRACE(name + " " + topology_name(t) + " " + std::to_string(p));
        const auto settings = check_platform_grammar(platform_xml(machine_spec(name), p, t), "x");
        // zcube's own flow settings, which it hands to SimGrid; SMPI's are not among them.
        ASSERT_EQ(settings.size(), 2u);
        EXPECT_EQ(settings[0].key, "network/model");
        EXPECT_EQ(settings[1].key, "network/crosstraffic");
      }
}

TEST(PlatformGrammar, ElementsZcubeDoesNotModelAreNamedWithTheirLine) {
  for (const std::string e : {"actor", "trace", "include", "router", "backbone", "peer", "disk",
                              "bypassRoute", "AS", "storage_type", "whatever"}) {
    SCOPED_TRACE(e);
    const std::string x = grammar_replaced(grammar_ring, "    </zone>\n",
                                           "      <" + e + " id=\"x\"/>\n    </zone>\n");
    const std::string why = grammar_refusal(x);
    EXPECT_NE(
        why.find("p.xml:" + std::to_string(grammar_line_of(x, "<" + e + " ")) + ": <" + e + ">"),
        std::string::npos)
        << why;
  }
}

TEST(PlatformGrammar, AttributesZcubeDoesNotModelAreRefused) {
  const std::vector<std::pair<std::string, std::string>> cases = {{"speed_file", "/etc/hostname"},
                                                                  {"availability_file", "x"},
                                                                  {"state_file", "x"},
                                                                  {"pstate", "0"},
                                                                  {"coordinates", "0 0 0"},
                                                                  {"bogus", "1"}};
  for (const auto& [attribute, value] : cases)
    for (const std::string element : {"<host id=\"node1\"", "<link id=\"ch-0-1\""}) {
      SCOPED_TRACE(element + " " + attribute);
      const std::string x =
          grammar_replaced(grammar_ring, element, element + " " + attribute + "=\"" + value + "\"");
      EXPECT_NE(grammar_refusal(x).find("attribute " + attribute + ": "), std::string::npos)
          << grammar_refusal(x);
    }
}

TEST(PlatformGrammar, ValuesOutsideTheModelAreRefused) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"core=\"", "<host id=\"node1\" core=\"0\""},
      {"core=\"", "<host id=\"node1\" core=\"99999999999\""},
      {"sharing_policy=\"WIFI\"", "<link id=\"ch-0-1\" sharing_policy=\"WIFI\""},
      {"speed=\"16Mf,8Mf\"", "<host id=\"node1\" speed=\"16Mf,8Mf\""},
      {"routing=\"Vivaldi\"", "<zone id=\"v\" routing=\"Vivaldi\""}};
  for (const auto& [named, edit] : cases) {
    SCOPED_TRACE(edit);
    const std::string element = edit.substr(0, edit.find(' ', edit.find(' ') + 1));
    const std::string x =
        edit.starts_with("<zone")
            ? grammar_replaced(grammar_ring, "    <zone id=", edit + ">\n</zone>\n    <zone id=")
            : grammar_replaced(grammar_ring, element, edit);
    EXPECT_NE(grammar_refusal(x).find(named), std::string::npos) << grammar_refusal(x);
  }
  const std::string radical =
      grammar_replaced(grammar_cube, "radical=\"0-3\"", "radical=\"0-99999999999\"");
  EXPECT_NE(grammar_refusal(radical).find("radical=\"0-99999999999\""), std::string::npos);
  const std::string overlap =
      grammar_replaced(grammar_cube, "radical=\"0-3\"", "radical=\"0-2,2\"");
  EXPECT_NE(grammar_refusal(overlap).find("node 2 is named twice"), std::string::npos);
}

TEST(PlatformGrammar, IdsDeclaredTwiceAreRefused) {
  const std::string link = "      <link id=\"ch-0-1\" bandwidth=\"1.7MBps\" latency=\"0s\"/>\n";
  EXPECT_NE(grammar_refusal(grammar_replaced(grammar_ring, link, link + link))
                .find("the link 'ch-0-1' a second"),
            std::string::npos);
  const std::string host = "<host id=\"srm\" speed=\"16Mf\"/>";
  EXPECT_NE(grammar_refusal(grammar_replaced(grammar_cube, host, host + host))
                .find("the host 'srm' a second"),
            std::string::npos);
  // A host the cluster declares already.
  const std::string again =
      grammar_replaced(grammar_cube, host, "<host id=\"node2\" speed=\"16Mf\"/>");
  EXPECT_NE(grammar_refusal(again).find("the host 'node2' a second"), std::string::npos);
}

TEST(PlatformGrammar, NestedZonesStopAtFourLevels) {
  for (int depth : {3, 4, 50, 500, 5000}) {
    SCOPED_TRACE(depth);
    std::string open, close;
    for (int d = 0; d < depth; ++d)
      open += "<zone id=\"w" + std::to_string(d) + "\" routing=\"Full\">", close += "</zone>";
    const std::string x = "<platform version=\"4.1\">" + open + close + "</platform>";
    const std::string why = grammar_refusal(x);
    if (depth <= 4)
      EXPECT_EQ(why, "");
    else
      EXPECT_NE(why.find("nested 5 deep"), std::string::npos) << why;
  }
}

TEST(PlatformGrammar, ConfigSettingsGoThroughTheCfgAllowList) {
  auto with = [](const std::string& key, const std::string& value) {
    return grammar_replaced(grammar_cube, "  </config>",
                            "    <prop id=\"" + key + "\" value=\"" + value + "\"/>\n  </config>");
  };
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, std::string>>{{"contexts/stack-size", "1"},
                                                        {"contexts/nthreads", "8"},
                                                        {"maxmin/precision", "0"},
                                                        {"network/bandwidth-factor", "0"},
                                                        {"tracing", "yes"},
                                                        {"tracing/filename", "t.trace"},
                                                        {"smpi/simulate-computation", "no"}}) {
    SCOPED_TRACE(key);
    const std::string why = grammar_refusal(with(key, value));
    EXPECT_NE(why.find("<config> <prop id=\"" + key + "\">"), std::string::npos) << why;
  }
  const auto settings = check_platform_grammar(with("contexts/stack-size", "512"), "p.xml");
  ASSERT_EQ(settings.size(), 3u);
  EXPECT_EQ(settings[2].key, "contexts/stack-size");
  EXPECT_EQ(settings[2].value, "512");
  const std::string twice =
      grammar_replaced(grammar_cube, "network/model\" value=\"CM02\"/>",
                       "network/model\" value=\"CM02\"/><prop id=\"network/model\" "
                       "value=\"LV08\"/>");
  EXPECT_NE(grammar_refusal(twice).find("is given twice"), std::string::npos);
}

TEST(PlatformGrammar, TextThatIsNotAPlatformIsRefusedWithItsLine) {
  EXPECT_NE(grammar_refusal("").find("not well-formed XML"), std::string::npos);
  EXPECT_NE(
      grammar_refusal(grammar_cube.substr(0, grammar_cube.size() / 2)).find("not well-formed XML"),
      std::string::npos);
  EXPECT_NE(grammar_refusal("<zone/>").find("its root element must be <platform>"),
            std::string::npos);
  EXPECT_NE(grammar_refusal("<platform version=\"4.1\"/>").find("without a <zone>"),
            std::string::npos);
  const std::string zone = "<zone id=\"z\" routing=\"None\"/>";
  EXPECT_NE(grammar_refusal("<platform version=\"4.1\">" + zone +
                            "<zone id=\"y\" routing=\"None\"/>" + "</platform>")
                .find("a second <zone>"),
            std::string::npos);
  EXPECT_NE(grammar_refusal("<platform version=\"4.1\">" + zone + "<config/></platform>")
                .find("<config> after"),
            std::string::npos);
  EXPECT_NE(grammar_refusal(grammar_replaced(grammar_cube, "version=\"4.1\"", "version=\"3\""))
                .find("4.1"),
            std::string::npos);
  const std::string text =
      grammar_replaced(grammar_cube, "  </zone>\n</platform>", "hello\n  </zone>\n</platform>");
  EXPECT_NE(grammar_refusal(text).find("text inside <zone>"), std::string::npos);
}

} // namespace
} // namespace zc
