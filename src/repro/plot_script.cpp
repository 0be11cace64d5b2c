#include "repro/plot_script.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
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

PlotOutcome plot_outcome(int wait_status) {
  if (!WIFEXITED(wait_status)) return PlotOutcome::failed;
  if (WEXITSTATUS(wait_status) == 0) return PlotOutcome::drawn;
  return WEXITSTATUS(wait_status) == kPlotLibraryMissing ? PlotOutcome::library_missing
                                                         : PlotOutcome::failed;
}

PlotOutcome plot_script_outcome(const std::string& root, const std::vector<std::string>& args) {
  std::vector<std::string> a = {"--units", unit_tables()};
  a.insert(a.end(), args.begin(), args.end());
  return python_script_outcome(root, "scripts/plot_results.py", a);
}

bool run_plot_script(const std::string& root, const std::vector<std::string>& args) {
  return plot_script_outcome(root, args) == PlotOutcome::drawn;
}

bool run_python_script(const std::string& root, const std::string& script,
                       const std::vector<std::string>& args) {
  return python_script_outcome(root, script, args) == PlotOutcome::drawn;
}

PlotOutcome python_script_outcome(const std::string& root, const std::string& script,
                                  const std::vector<std::string>& args) {
  std::vector<std::string> words = {python_interpreter(), root + "/" + script};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words)
    argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    return PlotOutcome::failed;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return PlotOutcome::failed;
  return plot_outcome(status);
}

BackgroundPlots::BackgroundPlots(const std::string& root) {
  std::vector<std::string> words = {python_interpreter(), root + "/scripts/plot_results.py",
                                    "--units", unit_tables(), "--arguments-on-stdin"};
  std::vector<char*> argv;
  for (auto& w : words)
    argv.push_back(w.data());
  argv.push_back(nullptr);
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return;
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_adddup2(&fa, fds[0], 0);
  pid_t pid = -1;
  if (posix_spawnp(&pid, argv[0], &fa, nullptr, argv.data(), environ) == 0) pid_ = pid;
  posix_spawn_file_actions_destroy(&fa);
  close(fds[0]);
  if (pid_ > 0)
    to_script_ = fds[1];
  else
    close(fds[1]);
}

BackgroundPlots::~BackgroundPlots() {
  wait();
}

void BackgroundPlots::draw(const std::vector<std::string>& args) {
  drawing_ = true;
  say(nlohmann::json(args).dump() + "\n"); // one line: JSON escapes any newline in an argument
}

void BackgroundPlots::say(const std::string& line) {
  if (to_script_ < 0) return;
  // A script that has already died must not take zcube with it (SIGPIPE): wait() reports it.
  struct sigaction ignore = {}, old = {};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &ignore, &old);
  for (std::size_t at = 0; at < line.size();) {
    const ssize_t n = write(to_script_, line.data() + at, line.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    at += std::size_t(n);
  }
  sigaction(SIGPIPE, &old, nullptr);
}

PlotOutcome BackgroundPlots::wait() {
  if (to_script_ >= 0) {
    close(to_script_); // end of input: nothing more is drawn
    to_script_ = -1;
  }
  if (pid_ <= 0) return outcome_;
  if (!drawing_) kill(pid_, SIGTERM); // (an error before draw(): not worth its start-up)
  int status = 0;
  wait_child(pid_, &status, 0, &cost_);
  pid_ = 0;
  outcome_ = plot_outcome(status);
  return outcome_;
}

} // namespace zc
