// A plain SimGrid program, as a SimGrid user writes one: an S4U engine that loads a platform file
// and nothing of zcube (no flag declared beforehand, no zcube library linked). It prints the
// hosts it found and the route length from node0 to every other host, and exits 0; SimGrid itself
// aborts on a file it cannot load (an undeclared <config> key, a bad route).
#include <cstdio>

#include <simgrid/s4u.hpp>

int main(int argc, char** argv) {
  simgrid::s4u::Engine e(&argc, argv);
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s platform.xml\n", argv[0]);
    return 2;
  }
  e.load_platform(argv[1]);
  e.seal_platform();
  const simgrid::s4u::Host* from = e.host_by_name_or_null("node0");
  if (from == nullptr) {
    std::fprintf(stderr, "%s: no host node0\n", argv[1]);
    return 1;
  }
  for (const simgrid::s4u::Host* to : e.get_all_hosts()) {
    std::vector<simgrid::s4u::Link*> links;
    double latency = 0;
    from->route_to(to, links, &latency);
    if (to != from && links.empty()) {
      std::fprintf(stderr, "%s: no route node0 -> %s\n", argv[1], to->get_cname());
      return 1;
    }
  }
  std::printf("%s: %zu hosts\n", argv[1], e.get_host_count());
  return 0;
}
