// zcube: simulator of 1990s hypercube multicomputers running parallel z-buffer renderers.
// Exit status: 0 success, 2 usage or input error (one line on stderr naming file, line, reason),
// 1 anything else.
#include <cstdio>
#include <exception>
#include <iostream>

#include "cli/command.hpp"
#include "util/error.hpp"

namespace zc::cli {
std::map<std::string, CommandInfo>& registry() {
  static std::map<std::string, CommandInfo> r;
  return r;
}
} // namespace zc::cli

static void usage(std::ostream& os) {
  os << "usage: zcube <command> [options]   (zcube <command> --help for its "
        "options)\n\ncommands:\n";
  for (const auto& [name, info] : zc::cli::registry())
    os << "  " << name << std::string(name.size() < 12 ? 12 - name.size() : 1, ' ') << info.summary
       << "\n";
}

int main(int argc, char** argv) {
  if (argc < 2) {
    usage(std::cerr);
    return 2;
  }
  const std::string cmd = argv[1];
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    usage(std::cout);
    return 0;
  }
  auto& reg = zc::cli::registry();
  auto it = reg.find(cmd);
  if (it == reg.end()) {
    std::cerr << "zcube: error: unknown command '" << cmd << "' (zcube --help lists them)\n";
    return 2;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  try {
    return it->second.run(args);
  } catch (const zc::InputError& e) {
    std::cerr << "zcube: error: " << e.what() << "\n";
    return 2;
  } catch (const zc::UsageError& e) {
    std::cerr << "zcube: error: " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "zcube: error: out of host memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "zcube: error: " << e.what() << "\n";
    return 1;
  }
}
