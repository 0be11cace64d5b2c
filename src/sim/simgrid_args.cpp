#include "sim/simgrid_args.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <simgrid/s4u.hpp>

#include "util/error.hpp"
#include "util/fork_pipe.hpp"

namespace zc {

namespace {

// In the child: an engine with the settings and a platform of one host (the models are made when
// it loads); stderr goes to fd, the exit status says whether SimGrid accepted them.
[[noreturn]] void try_settings(const std::vector<std::string>& user, const std::string& platform,
                               int fd) {
  dup2(fd, STDERR_FILENO);
  std::vector<std::string> args = {"zcube", "--log=root.thres:critical"};
  args.insert(args.end(), user.begin(), user.end());
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  int argc = int(argv.size());
  try {
    simgrid::s4u::Engine e(&argc, argv.data());
    e.load_platform(platform);
    e.run();
  } catch (const std::exception& ex) {
    const std::string msg = ex.what();
    (void)!write(fd, msg.data(), msg.size());
    _exit(3);
  }
  _exit(0);
}

// The reason in what SimGrid printed: its first line, without the log prefix.
std::string reason(std::string text) {
  const auto crit = text.find("CRITICAL] ");
  if (crit != std::string::npos) text = text.substr(crit + 10);
  text = text.substr(0, text.find('\n'));
  return text.empty() ? "refused by SimGrid" : text;
}

} // namespace

void check_simgrid_args(const std::vector<std::string>& args) {
  if (args.empty()) return;
  const std::string platform = (std::filesystem::temp_directory_path() /
                                ("zcube-" + std::to_string(getpid()) + "-cfg-check.xml"))
                                   .string();
  std::ofstream(platform) << "<?xml version='1.0'?>\n"
                             "<!DOCTYPE platform SYSTEM \"https://simgrid.org/simgrid.dtd\">\n"
                             "<platform version=\"4.1\"><zone id=\"z\" routing=\"Full\">"
                             "<host id=\"h\" speed=\"1Gf\"/></zone></platform>\n";
  const PipedChild child = fork_with_pipe();
  if (child.pid == 0) try_settings(args, platform, child.fd);
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = read(child.fd, buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    out.append(buf, std::size_t(n));
  }
  close(child.fd);
  int status = 0;
  while (waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::filesystem::remove(platform);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  std::string given;
  for (const auto& a : args)
    given += (given.empty() ? "" : " ") + a;
  throw UsageError(given + ": " + reason(out));
}

} // namespace zc
