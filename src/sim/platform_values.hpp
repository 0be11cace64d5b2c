#pragma once
// The values of a platform file's attributes and properties that zcube models, and why it cannot
// model the rest (sim/platform_grammar.hpp checks a file with them). Each *_problem function
// returns the empty string for a value zcube reads, else the reason, to be shown after the
// attribute.
#include <string>
#include <utility>
#include <vector>

namespace zc {

enum class AttributeKind {
  Name,            // an id: not empty, no control characters
  Text,            // any text (a property's value, a cluster's prefix and suffix)
  Version,         // 4.1
  Routing,         // Full, Floyd, Dijkstra, DijkstraCache, None
  Speed,           // one speed with its unit ("16Mf"), > 0
  Bandwidth,       // one rate with its unit ("2.8MBps"), > 0
  Latency,         // one time with its unit ("10us")
  Core,            // 1
  Radical,         // node numbers "a-b,c", at most 1024 of them, none twice
  Dimensions,      // a torus's "2,2,2": each 1..1024, their product at most 1024
  ClusterTopology, // TORUS
  ClusterSharing,  // SPLITDUPLEX
  LinkSharing,     // SHARED
  YesNo,           // YES, NO, yes, no
};

std::string attribute_value_problem(AttributeKind kind, const std::string& value);

// Why zcube cannot model an element, or an attribute of an element it models.
std::string unmodelled_element_reason(const std::string& element);
std::string unmodelled_attribute_reason(const std::string& element, const std::string& attribute);

// A radical's node numbers as ranges [a, b], and how many they are; a torus's node count. For
// values attribute_value_problem accepted.
std::vector<std::pair<int, int>> radical_ranges(const std::string& radical);
long radical_count(const std::string& radical);
long dimensions_product(const std::string& dimensions);

// A <config> setting: the --cfg allow-list and ranges (sim/simgrid_args.hpp), SMPI's settings with
// the values zcube writes, and smpi/or (files of earlier zcube versions).
std::string config_setting_problem(const std::string& key, const std::string& value);

// A zone property: one of the zcube.* properties zcube reads (platforms/README.md).
std::string zone_property_problem(const std::string& id);

} // namespace zc
