#pragma once
// Loads a platform file into the SimGrid engine and reads the machine model back from what
// SimGrid loaded (platforms/README.md): channel bandwidth and latency from the links, start-up from
// SMPI's receive overhead (the nodes' smpi/or property), CPU speed from the hosts, switching,
// memory and cycles from the machine zone's zcube.* properties. Every figure is checked (finite, in
// range) and a bad one is an InputError naming the file and the attribute, before any simulation
// starts.
#include <string>
#include <vector>

#include <simgrid/s4u.hpp>

#include "machine/machine.hpp"

namespace zc {

class WhatIfs;

struct PlatformModel {
  std::string machine;
  Topology topology = Topology::Cube;
  int nodes = 0;
  NetworkParams net;
  std::vector<CostTable> cost; // per node: cycles / host speed
  std::vector<double> memory;  // per node
  double os_resident = 0;      // per node: the operating system's share of `memory`
};

// Declares smpi/or, which SimGrid declares only under SMPI, so that zcube's engine still accepts
// files written before the start-up became a host property (they set it in <config>); current
// files need no declaration. Call before creating the engine.
void declare_platform_flags();

// Loads `xml` (the text of a built-in machine) or the file `path` into `e`; `label` names it in
// errors. No temporary file is written.
void load_platform_text(simgrid::s4u::Engine& e, const std::string& xml, const std::string& label);
void load_platform_file(simgrid::s4u::Engine& e, const std::string& path);


// The checks load_platform_file makes before SimGrid reads the file (InputError naming the file,
// the line and the reason): the grammar zcube models (sim/platform_grammar.hpp), the declared
// routes (sim/platform_routes.hpp), then, in a process without a SimGrid engine yet, a trial load
// in a forked child (sim/platform_probe.hpp). A text this process has checked under the same path,
// or the process that forked it, is not checked again. Call it before creating the run's engine.
void check_platform_file(const std::string& path);

// The file's <config> settings as SimGrid arguments ("--cfg=key:value"), checked as --cfg is: a run
// passes them after zcube's own settings and before the user's --cfg.
std::vector<std::string> platform_file_settings(const std::string& path);

// The model of the platform loaded into `e` (sim/platform_read.cpp); InputError names `label`.
PlatformModel read_platform(const simgrid::s4u::Engine& e, const std::string& label);

// Whether a link is a T800-style duplex link (its two-way total; machine/platform_xml.hpp).
bool is_duplex_link(const std::string& name);

// The what-ifs (run/what_if.hpp), then the links set to what the fidelities need: bandwidth from
// the model, zero latency (zcube charges start-up and hops itself, so SimGrid's flow sharing is
// not weighted by route latency).
void apply_what_ifs(const WhatIfs& w, PlatformModel& m, simgrid::s4u::Engine& e);

} // namespace zc
