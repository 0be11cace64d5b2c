#include "sim/simgrid_args.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <simgrid/s4u.hpp>

#include "util/error.hpp"
#include "util/fork_pipe.hpp"

namespace zc {

namespace {

// The SimGrid settings zcube runs with (SimGrid 3.32's declarations, `--help-cfg`), each with the
// values that simulate correctly: a numeric range, a boolean or a list of names. Anything else is
// refused before the simulation; settings outside these ranges crashed (contexts/stack-size:1),
// aborted (maxmin/precision:1e10) or hung (surf/precision:0) SimGrid.
struct Setting {
  const char* key;
  enum class Kind { Bool, Int, Real, Choice } kind;
  double lo = 0, hi = 0;            // Int and Real: the closed range
  std::vector<std::string> choices; // Choice
  const char* why = "";             // the reason for the range, shown with it
};

Setting real(const char* key, double lo, double hi, const char* why) {
  return {key, Setting::Kind::Real, lo, hi, {}, why};
}
Setting integer(const char* key, double lo, double hi, const char* why) {
  return {key, Setting::Kind::Int, lo, hi, {}, why};
}
Setting choice(const char* key, std::vector<std::string> names) {
  return {key, Setting::Kind::Choice, 0, 0, std::move(names), ""};
}
Setting boolean(const char* key) {
  return {key, Setting::Kind::Bool, 0, 0, {}, ""};
}

const std::vector<Setting>& settings() {
  static const std::vector<Setting> s = {
      // The network model of the flow fidelity (platforms/README.md, "Network fidelity") and its
      // solver options.
      choice("network/model", {"CM02", "LV08"}),
      choice("network/optim", {"Lazy", "Full"}),
      boolean("network/crosstraffic"),
      boolean("network/maxmin-selective-update"),
      real("network/TCP-gamma", 0, 1e12, "bytes of TCP window, 0 for none"),
      real("network/bandwidth-factor", 1e-3, 1, "a fraction of the link bandwidth"),
      real("network/latency-factor", 0, 1e3, "a multiple of the link latency"),
      real("network/weight-S", 0, 1e9, "bytes"),
      real("network/loopback-lat", 0, 3600, "seconds"),
      real("network/loopback-bw", 1, 1e15, "bytes per second"),
      choice("cpu/optim", {"Lazy", "TI", "Full"}),
      boolean("cpu/maxmin-selective-update"),
      // Numerical precisions: zcube sets 1e-12 s and 1e-12; far coarser ones abort SimGrid or
      // round the nanoseconds the models charge, 0 or less never settles.
      real("maxmin/precision", 1e-15, 1e-5, "SimGrid's default is the coarsest"),
      real("surf/precision", 1e-15, 1e-9, "seconds; SimGrid's default is the coarsest"),
      // Actor contexts. Every actor of a run shares the run's state, so they run one at a time.
      choice("contexts/factory", {"raw", "ucontext", "boost", "thread"}),
      integer("contexts/stack-size", 256, 1048576,
              "KiB; smaller stacks overflow in zcube's renderers"),
      integer("contexts/guard-size", 0, 64, "memory pages"),
      integer("contexts/nthreads", 1, 1, "zcube's actors share the run's state"),
  };
  return s;
}

const Setting* find_setting(const std::string& key) {
  for (const auto& s : settings())
    if (key == s.key) return &s;
  return nullptr;
}

std::string known_keys() {
  std::string k;
  for (const auto& s : settings())
    k += (k.empty() ? "" : ", ") + std::string(s.key);
  return k;
}

std::string range_text(const Setting& s) {
  auto num = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.10g", v);
    return std::string(b);
  };
  switch (s.kind) {
  case Setting::Kind::Bool:
    return "yes/no, on/off, true/false or 1/0";
  case Setting::Kind::Choice: {
    std::string c;
    for (const auto& v : s.choices)
      c += (c.empty() ? "" : ", ") + v;
    return "one of " + c;
  }
  default:
    return (s.kind == Setting::Kind::Int ? "an integer in " : "a number in ") + num(s.lo) + ".." +
           num(s.hi) + (*s.why ? std::string(" (") + s.why + ")" : "");
  }
}

bool value_fits(const Setting& s, const std::string& v) {
  switch (s.kind) {
  case Setting::Kind::Bool: {
    static const std::set<std::string> b = {"yes", "no", "on", "off", "true", "false", "1", "0"};
    return b.count(v) > 0;
  }
  case Setting::Kind::Choice:
    return std::find(s.choices.begin(), s.choices.end(), v) != s.choices.end();
  default: {
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    if (v.empty() || *end || !std::isfinite(d) || d < s.lo || d > s.hi) return false;
    return s.kind == Setting::Kind::Real || d == std::floor(d);
  }
  }
}

// "--cfg=name:value" against the allow-list.
void check_cfg(const std::string& arg) {
  const std::string setting = arg.substr(6);
  const auto colon = setting.find(':');
  const std::string why = setting_problem(setting.substr(0, colon), setting.substr(colon + 1));
  if (!why.empty()) throw UsageError("--cfg " + setting + ": " + why);
}

// "--log=category.thres:level": the thresholds of SimGrid's log categories. Appenders and layouts
// (app, fmt, add) write files and reformat zcube's one-line errors, so they are not taken.
void check_log(const std::string& arg) {
  const std::string setting = arg.substr(6);
  static const std::regex form(R"(([A-Za-z0-9_]+)\.(thres|threshold)[:=](\w+))");
  static const std::set<std::string> levels = {"trace",   "debug", "verbose", "info",
                                               "warning", "error", "critical"};
  std::smatch m;
  if (!std::regex_match(setting, m, form) || !levels.count(m[3]))
    throw UsageError("--log " + setting +
                     ": expected category.thres:level with a level among trace, debug, verbose, "
                     "info, warning, error, critical (e.g. root.thres:warning)");
}

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

std::string setting_problem(const std::string& key, const std::string& value) {
  const Setting* s = find_setting(key);
  if (!s) return "not a SimGrid setting zcube runs with (" + known_keys() + ")";
  return value_fits(*s, value) ? "" : "expected " + range_text(*s);
}

void check_simgrid_args(const std::vector<std::string>& args) {
  if (args.empty()) return;
  for (const auto& a : args)
    if (a.starts_with("--cfg="))
      check_cfg(a);
    else if (a.starts_with("--log="))
      check_log(a);
    else
      throw UsageError(a + ": not a SimGrid setting (--cfg name:value or --log setting)");
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
