// zcube platform: prints the SimGrid platform XML of a machine model.
#include <iostream>

#include "cli/command.hpp"
#include "cli/parse.hpp"
#include "machine/platform_xml.hpp"

namespace zc::cli {

static int cmd_platform(std::vector<std::string> args) {
  CLI::App app{"Print the SimGrid platform XML of a machine model", "zcube platform"};
  std::string machine = "ipsc2", topology = "cube";
  int nodes = 1;
  app.add_option("--machine", machine, "ipsc2, ipsc860 or volvox")->capture_default_str();
  app.add_option("--nodes", nodes, "number of nodes")->capture_default_str();
  app.add_option("--topology", topology, "cube or ring")->capture_default_str();
  if (int rc = parse(app, args); rc >= 0) return rc;
  std::cout << platform_xml(machine_spec(machine), nodes, parse_topology(topology));
  return 0;
}

ZC_COMMAND("platform", "print the SimGrid platform XML of a machine model", cmd_platform);

} // namespace zc::cli
