#pragma once
// SimGrid 4.1 platform files of the modelled machines (platforms/README.md). One zone
// per machine: the nodes are a SimGrid TORUS cluster (a hypercube of dimension d is the torus
// 2x2x...x2, whose dimension-order routing is e-cube; a ring is the 1-D torus P), the host computer
// srm is a zone of its own linked to node0 by host-up/host-down. SimGrid reads every figure it
// can use: channel bandwidth and latency (the cluster's bw and lat), the CPU clock (host speed),
// the message start-up as SMPI's receive overhead (smpi/or, a property of every node, piecewise by
// size: the two protocols) and the host link's bandwidth and latency. The <config> block holds
// only settings every SimGrid program declares (an s4u program loads the file as is), those under
// which SimGrid's flow model times a lone message as zcube does (kFlowConfig). Links whose two
// directions carry less than twice the one-way rate in all (the Volvox's T800s) are written out
// instead of a cluster: a link per direction and a shared duplex-a-b link of the two-way total
// under both (docs/machines.md). What SimGrid has no notion of is a zcube.* property of the machine
// zone, stated once: switching, node memory, cycles per counted operation.
#include <string>
#include <utility>

#include "machine/machine.hpp"

namespace zc {

// SMPI adds a 16-byte MPI envelope to every message it times (smpi_request.cpp); the generator
// takes it off the start-up so that an SMPI program on the file sees zcube's T(m, h).
constexpr double kSmpiEnvelopeBytes = 16;

// What-ifs a written platform carries (`zcube platform --latency/--bandwidth/--cpu-scale`).
struct PlatformEdits {
  double cpu_scale = 1; // multiplies every CPU cost: the host speed is clock / cpu_scale
};

// The CPU clock of a machine's nodes (Hz), from its CPU model (machine/cpu_model.hpp): 16 MHz
// 80386 (iPSC/2), 40 MHz i860 XR (iPSC/860, Volvox). Costs are written as cycles = seconds x clock.
double cpu_clock_hz(const MachineSpec& spec);

std::string platform_xml(const MachineSpec& spec, int nodes, Topology topology,
                         const PlatformEdits& edits = {});

// Default file name: MACHINE-P.xml (cube) or MACHINE-ring-P.xml.
std::string platform_file_name(const std::string& machine, int nodes, Topology topology);

// Names used in the XML.
std::string node_host_name(int rank);
// The host computer: SRM, Intel's System Resource Manager, the iPSC's host (docs/glossary.md).
// The name is part of the platform-file format (a user's file names the host "srm", and zcube
// refuses a file without it), so it stays as the papers' machines had it.
constexpr const char* kHostComputerName = "srm";
constexpr const char* kHostUpLink = "host-up";
constexpr const char* kHostDownLink = "host-down";
// On machines whose links carry less than twice the one-way rate both ways busy (the Volvox), the
// shared link of the two-way total under the two directions of the channel between nodes a and b.
constexpr const char* kDuplexLinkPrefix = "duplex-";
std::string duplex_link_name(int a, int b);
// SMPI's receive overhead, read from a host's property of that name before the global setting.
constexpr const char* kStartupProperty = "smpi/or";
// Also the name of the global setting, which files written before the property carry in <config>.
constexpr const char* kStartupConfig = "smpi/or";
// The <config> of every file: CM02 flows (no latency and bandwidth factors of LV08), no
// cross-traffic (an acknowledgement does not load the reverse channel), SMPI's factors 1 (smpirun
// imposes network/model:SMPI, CM02 with those), and every message eager (SMPI charges smpi/or only
// on detached sends, below this size).
inline constexpr std::pair<const char*, const char*> kFlowConfig[] = {
    {"network/model", "CM02"},
    {"network/crosstraffic", "0"},
    {"smpi/bw-factor", "0:1"},
    {"smpi/lat-factor", "0:1"},
    {"smpi/send-is-detached-thresh", "1073741824"}};

} // namespace zc
