#include "sim/platform_grammar.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <set>

#include <pugixml.hpp>

#include "machine/platform_xml.hpp"
#include "sim/platform_values.hpp"
#include "sim/simgrid_args.hpp"
#include "util/error.hpp"

namespace zc {

namespace {

using Kind = AttributeKind;

struct Attribute {
  const char* name;
  Kind kind;
  bool required;
};

// The elements zcube models: their attributes and the elements they may hold.
struct Element {
  const char* name;
  std::vector<Attribute> attributes;
  std::vector<const char*> children;
};

const std::vector<Element>& grammar() {
  static const std::vector<Element> g = {
      {"platform", {{"version", Kind::Version, true}}, {"config", "zone"}},
      {"config", {{"id", Kind::Name, false}}, {"prop"}},
      {"prop", {{"id", Kind::Name, true}, {"value", Kind::Text, true}}, {}},
      {"zone",
       {{"id", Kind::Name, true}, {"routing", Kind::Routing, true}},
       {"prop", "host", "link", "cluster", "zone", "route", "zoneRoute"}},
      {"host",
       {{"id", Kind::Name, true}, {"speed", Kind::Speed, true}, {"core", Kind::Core, false}},
       {"prop"}},
      {"link",
       {{"id", Kind::Name, true},
        {"bandwidth", Kind::Bandwidth, true},
        {"latency", Kind::Latency, false},
        {"sharing_policy", Kind::LinkSharing, false}},
       {}},
      {"cluster",
       {{"id", Kind::Name, true},
        {"prefix", Kind::Text, true},
        {"suffix", Kind::Text, true},
        {"radical", Kind::Radical, true},
        {"speed", Kind::Speed, true},
        {"bw", Kind::Bandwidth, true},
        {"lat", Kind::Latency, false},
        {"topology", Kind::ClusterTopology, true},
        {"topo_parameters", Kind::Dimensions, true},
        {"sharing_policy", Kind::ClusterSharing, true},
        {"core", Kind::Core, false}},
       {"prop"}},
      {"route",
       {{"src", Kind::Name, true}, {"dst", Kind::Name, true}, {"symmetrical", Kind::YesNo, false}},
       {"link_ctn"}},
      {"zoneRoute",
       {{"src", Kind::Name, true},
        {"dst", Kind::Name, true},
        {"gw_src", Kind::Name, true},
        {"gw_dst", Kind::Name, true},
        {"symmetrical", Kind::YesNo, false}},
       {"link_ctn"}},
      {"link_ctn", {{"id", Kind::Name, true}}, {}},
  };
  return g;
}

const Element* rule(const std::string& name) {
  for (const auto& e : grammar())
    if (name == e.name) return &e;
  return nullptr;
}

std::string list(const std::vector<const char*>& names) {
  std::string s;
  for (const char* n : names)
    s += (s.empty() ? "" : ", ") + std::string("<") + n + ">";
  return s.empty() ? "nothing" : s;
}

// Zones nest this deep at most: the machine's zone, a wrapper around it, and their inner zones.
constexpr int kMaxZoneDepth = 4;

class Checker {
public:
  Checker(const std::string& xml, std::string label) : xml_(xml), label_(std::move(label)) {}

  std::vector<PlatformSetting> run() {
    pugi::xml_document doc;
    const unsigned options = pugi::parse_default | pugi::parse_doctype;
    const pugi::xml_parse_result r = doc.load_buffer(xml_.data(), xml_.size(), options);
    if (!r) fail_at(r.offset, std::string("not well-formed XML: ") + r.description());
    pugi::xml_node root;
    for (pugi::xml_node n : doc.children()) {
      if (n.type() == pugi::node_doctype && std::strchr(n.value(), '['))
        fail(n, "<!DOCTYPE> with an internal subset: zcube reads plain platform files");
      if (n.type() != pugi::node_element) continue;
      if (root) fail(n, "<" + std::string(n.name()) + ">: a file holds one <platform>");
      root = n;
    }
    if (!root || std::string(root.name()) != "platform")
      fail(root, "not a SimGrid platform (its root element must be <platform>)");
    element(root, 0);
    return settings_;
  }

private:
  int line_of(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    const auto end = xml_.begin() + std::min<std::ptrdiff_t>(offset, std::ptrdiff_t(xml_.size()));
    return 1 + int(std::count(xml_.begin(), end, '\n'));
  }
  [[noreturn]] void fail_at(std::ptrdiff_t offset, const std::string& why) const {
    throw InputError(label_, line_of(offset), why);
  }
  [[noreturn]] void fail(pugi::xml_node n, const std::string& why) const {
    fail_at(n ? n.offset_debug() : -1, why);
  }

  void attributes(pugi::xml_node n, const Element& e) {
    std::set<std::string> seen;
    for (pugi::xml_attribute a : n.attributes()) {
      const std::string name = a.name();
      const auto it = std::find_if(e.attributes.begin(), e.attributes.end(),
                                   [&](const Attribute& x) { return name == x.name; });
      if (it == e.attributes.end())
        fail(n, "<" + std::string(e.name) + "> attribute " + name + ": " +
                    unmodelled_attribute_reason(e.name, name));
      if (!seen.insert(name).second)
        fail(n, "<" + std::string(e.name) + "> attribute " + name + " is given twice");
      const std::string why = attribute_value_problem(it->kind, a.value());
      if (!why.empty())
        fail(n, "<" + std::string(e.name) + "> " + name + "=\"" + a.value() + "\": " + why);
    }
    for (const Attribute& a : e.attributes)
      if (a.required && !seen.count(a.name))
        fail(n, "<" + std::string(e.name) + "> needs the attribute " + a.name);
  }

  void element(pugi::xml_node n, int zone_depth) {
    const std::string name = n.name();
    const Element* e = rule(name);
    if (!e) fail(n, "<" + name + ">: " + unmodelled_element_reason(name));
    attributes(n, *e);
    if (name == "zone" && zone_depth + 1 > kMaxZoneDepth)
      fail(n, "<zone> nested " + std::to_string(zone_depth + 1) + " deep: zcube reads at most " +
                  std::to_string(kMaxZoneDepth) + " (the machine's zone, a wrapper, their zones)");
    check_cluster(n, name);
    check_unique(n, name);
    check_platform_children(n, name);
    for (pugi::xml_node c : n.children()) {
      if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata)
        fail(c, "text inside <" + name + ">: a platform holds elements only");
      if (c.type() != pugi::node_element) continue;
      const std::string child = c.name();
      if (std::find_if(e->children.begin(), e->children.end(),
                       [&](const char* k) { return child == k; }) == e->children.end()) {
        if (!rule(child)) fail(c, "<" + child + ">: " + unmodelled_element_reason(child));
        fail(c, "<" + child + "> inside <" + name + ">: <" + name + "> holds " + list(e->children));
      }
      if (child == "prop") {
        prop(c, name);
        continue;
      }
      element(c, zone_depth + (name == "zone" ? 1 : 0));
    }
  }

  // A platform is its <config> first, then the machine's zone.
  void check_platform_children(pugi::xml_node n, const std::string& name) {
    if (name != "platform") return;
    int zones = 0, seen = 0;
    for (pugi::xml_node c : n.children()) {
      if (c.type() != pugi::node_element) continue;
      const std::string child = c.name();
      if (child == "config" && seen > 0)
        fail(c, "<config> after another element: a <platform> opens with its one <config>");
      if (child == "zone" && ++zones > 1)
        fail(c, "a second <zone> in <platform>: the machine is one zone (wrap zones in one)");
      ++seen;
    }
    if (zones == 0) fail(n, "<platform> without a <zone>: no machine to model");
  }

  // A cluster's torus must hold as many nodes as its radical names.
  void check_cluster(pugi::xml_node n, const std::string& name) {
    if (name != "cluster") return;
    const long nodes = radical_count(n.attribute("radical").value());
    const long torus = dimensions_product(n.attribute("topo_parameters").value());
    if (nodes != torus)
      fail(n, "<cluster> radical=\"" + std::string(n.attribute("radical").value()) + "\" names " +
                  std::to_string(nodes) + " nodes, but the torus " +
                  n.attribute("topo_parameters").value() + " has " + std::to_string(torus));
  }

  // SimGrid ends the process on a host, link or zone declared twice.
  void check_unique(pugi::xml_node n, const std::string& name) {
    auto once = [&](std::set<std::string>& ids, const std::string& id, const char* what) {
      if (!ids.insert(id).second)
        fail(n, "<" + name + "> declares the " + what + " '" + id + "' a second time");
    };
    const std::string id = n.attribute("id").value();
    if (name == "host") once(hosts_, id, "host");
    if (name == "link") once(links_, id, "link");
    if (name == "zone" || name == "cluster") once(zones_, id, "zone");
    if (name != "cluster") return;
    const std::string prefix = n.attribute("prefix").value(),
                      suffix = n.attribute("suffix").value();
    for (auto [lo, hi] : radical_ranges(n.attribute("radical").value()))
      for (int i = lo; i <= hi; ++i)
        once(hosts_, prefix + std::to_string(i) + suffix, "host");
  }

  void prop(pugi::xml_node p, const std::string& parent) {
    const std::string id = p.attribute("id").value(), value = p.attribute("value").value();
    if (!props_[p.parent().offset_debug()].insert(id).second)
      fail(p, "<" + parent + "> property '" + id + "' is given twice");
    std::string why;
    if (parent == "config") {
      why = config_setting_problem(id, value);
      if (why.empty() && !id.starts_with("smpi/")) settings_.push_back({id, value});
    } else if (parent == "zone") {
      why = zone_property_problem(id);
    } else if (id != kStartupProperty) {
      why = "zcube reads one property of a host or cluster, " + std::string(kStartupProperty) +
            " (the message start-up)";
    }
    if (!why.empty()) fail(p, "<" + parent + "> <prop id=\"" + id + "\">: " + why);
  }

  const std::string& xml_;
  std::string label_;
  std::vector<PlatformSetting> settings_;
  std::map<std::ptrdiff_t, std::set<std::string>> props_; // by the holder's offset
  std::set<std::string> hosts_, links_, zones_;
};

} // namespace

std::vector<PlatformSetting> check_platform_grammar(const std::string& xml,
                                                    const std::string& label) {
  return Checker(xml, label).run();
}

} // namespace zc
