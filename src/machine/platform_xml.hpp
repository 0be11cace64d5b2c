#pragma once
// SimGrid 4.1 platform files of the modelled machines (DESIGN §5): hosts node0..nodeP-1 and the
// host computer srm; one directed link per channel direction (full duplex) with the channel's
// bandwidth and zero latency (start-up is charged by the communication layer, so that SimGrid's
// flow sharing is not weighted by latency); explicit routes (e-cube on the cube). Every model
// figure is a property: machine-level ones on the zone, the CPU cost table and memory on hosts.
#include <string>

#include "machine/machine.hpp"

namespace zc {

std::string platform_xml(const MachineSpec& spec, int nodes, Topology topology);

// Committed file name: platforms/MACHINE-P.xml (cube) or platforms/MACHINE-ring-P.xml.
std::string platform_file_name(const std::string& machine, int nodes, Topology topology);

// Names used in the XML.
std::string node_host_name(int rank);
constexpr const char* kHostComputerName = "srm";
std::string channel_link_name(int from, int to);

} // namespace zc
