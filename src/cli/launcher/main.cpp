// The zcube command's first step: it answers `zcube run --list` from the algorithm registry alone,
// and becomes zcube-full (execv: same process, arguments, exit status and signals) for anything
// else. zcube-full links SimGrid, whose ns-3 libraries make the dynamic loader relocate some 40
// libraries at every start: most of a listing's time, work a listing does not need
// (results/simulator_costs.md).
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "algo/algorithm.hpp"

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "run") == 0 && std::strcmp(argv[2], "--list") == 0) {
    for (const auto& a : zc::algorithms()) // as cmd_run.cpp lists them
      std::cout << a.name << "  " << a.summary << "\n";
    errno = 0;
    if (std::cout.flush() && std::fflush(stdout) == 0 && !std::ferror(stdout)) return 0;
    const int err = errno; // the listing is the result: a write that failed fails the command
    std::cerr << "zcube: error: cannot write standard output"
              << (err ? std::string(": ") + std::strerror(err) : std::string()) << "\n";
    return 1;
  }
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  if (ec) dir = fs::path(argv[0]).parent_path();
  const std::string full = (dir / "zcube-full").string();
  execv(full.c_str(), argv);
  std::cerr << "zcube: error: cannot start " << full << ": " << std::strerror(errno) << "\n";
  return 1;
}
