#pragma once
// Sub-command registry: each src/cli/cmd_*.cpp registers itself with ZC_COMMAND, so adding a
// command touches no shared file.
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace zc::cli {

using CommandFn =
    std::function<int(std::vector<std::string> args)>; // args exclude the command name

struct CommandInfo {
  std::string summary;
  CommandFn run;
};

std::map<std::string, CommandInfo>& registry();

struct Registrar {
  Registrar(const char* name, const char* summary, CommandFn fn) {
    registry()[name] = {summary, std::move(fn)};
  }
};

#define ZC_COMMAND(name, summary, fn) static ::zc::cli::Registrar zc_cmd_reg_##fn(name, summary, fn)

} // namespace zc::cli
