#include "repro/plot_script.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "machine/units.hpp"

extern char** environ;

namespace zc {

std::string python_interpreter() {
  if (const char* p = std::getenv("ZCUBE_PYTHON"); p && *p) return p;
  return std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

namespace {

// SimGrid's unit tables as JSON, as `zcube units --json` prints them: {"time": {"us": 1e-06, ...},
// "bandwidth": ..., "size": ..., "speed": ...}.
std::string unit_tables() {
  nlohmann::json j;
  j["time"] = time_units();
  j["bandwidth"] = bandwidth_units();
  j["size"] = size_units();
  j["speed"] = speed_units();
  return j.dump();
}

} // namespace

bool run_plot_script(const std::string& root, const std::vector<std::string>& args) {
  std::vector<std::string> a = {"--units", unit_tables()};
  a.insert(a.end(), args.begin(), args.end());
  return run_python_script(root, "scripts/plot_results.py", a);
}

bool run_python_script(const std::string& root, const std::string& script,
                       const std::vector<std::string>& args) {
  std::vector<std::string> words = {python_interpreter(), root + "/" + script};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words)
    argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return false;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

} // namespace zc
