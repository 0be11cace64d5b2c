#include "sim/platform_probe.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>

#include <simgrid/s4u.hpp>

#include "sim/platform_load.hpp"
#include "util/error.hpp"
#include "util/error_text.hpp"
#include "util/fork_pipe.hpp"

namespace zc {

namespace {

// The first line of what the child said that gives a reason: an InputError's own text, else
// SimGrid's message after its "[category/CRITICAL] " prefix.
std::string probe_reason(const std::string& out) {
  std::size_t at = 0;
  while (at < out.size()) {
    const std::size_t end = std::min(out.find('\n', at), out.size());
    std::string line = out.substr(at, end - at);
    at = end + 1;
    if (line.starts_with("input: ")) return line.substr(7);
    const auto crit = line.find("CRITICAL] ");
    if (crit != std::string::npos) return line.substr(crit + 10);
  }
  return "";
}

// In the child: SimGrid's messages to the pipe, the platform loaded and read as a run reads it.
// An InputError's reason, or SimGrid's exception, is written as a line "input: reason".
[[noreturn]] void load_in_child(const std::string& path, std::vector<std::string> settings,
                                int fd) {
  dup2(fd, STDERR_FILENO);
  alarm(kProbeSeconds);
  std::vector<std::string> args = {"zcube", "--log=root.thres:critical"};
  args.insert(args.end(), settings.begin(), settings.end());
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  int argc = int(argv.size());
  std::string said;
  int rc = 0;
  try {
    declare_platform_flags();
    simgrid::s4u::Engine e(&argc, argv.data());
    e.load_platform(path); // checked by the parent: load_platform_file would check it again
    read_platform(e, path);
  } catch (const InputError& ex) {
    said = "input: " + ex.reason() + "\n", rc = 3;
  } catch (const std::exception& ex) {
    said = "input: SimGrid cannot load it: " + one_line(ex.what()) + "\n", rc = 3;
  }
  (void)!write(fd, said.data(), said.size());
  _exit(rc);
}

} // namespace

void probe_platform_file(const std::string& path, const std::vector<std::string>& settings) {
  const PipedChild child = fork_with_pipe();
  if (child.pid == 0) load_in_child(path, settings, child.fd);
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = read(child.fd, buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    if (out.size() < (1u << 16)) out.append(buf, std::size_t(n));
  }
  close(child.fd);
  int status = 0;
  while (waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  std::string why = probe_reason(out);
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
    why = "SimGrid did not finish loading it in " + std::to_string(kProbeSeconds) + " s";
  else if (why.empty())
    why = WIFSIGNALED(status)
              ? std::string("SimGrid ended while loading it (") + strsignal(WTERMSIG(status)) + ")"
              : "SimGrid refused it";
  else if (!(WIFEXITED(status) && WEXITSTATUS(status) == 3))
    why = "SimGrid refused it: " + why;
  throw InputError(path, 0, why);
}

} // namespace zc
