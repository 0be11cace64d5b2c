// zcube: simulator of 1990s hypercube multicomputers running parallel z-buffer renderers.
// Exit status: 0 success, 2 usage or input error (one line on stderr naming file, line, reason),
// 1 anything else (a failed write to standard output too).
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <sstream>

#include <xbt/base.h> // before simgrid/version.h, which uses its macros

#include <simgrid/version.h>

#include "cli/command.hpp"
#include "repro/provenance.hpp"
#include "run/run_flags.hpp"
#include "util/error.hpp"
#include "util/error_text.hpp"

namespace zc::cli {
std::map<std::string, CommandInfo>& registry() {
  static std::map<std::string, CommandInfo> r;
  return r;
}
} // namespace zc::cli

static void usage(std::ostream& os) {
  os << "usage: zcube <command> [options] [-q]   (zcube help <command> or zcube <command> "
        "--help for its options; zcube help flags for the run flags; -q: errors only on standard "
        "error; zcube --version)\n\ncommands:\n";
  for (const auto& [name, info] : zc::cli::registry())
    os << "  " << name << std::string(name.size() < 12 ? 12 - name.size() : 1, ' ') << info.summary
       << "\n";
}

// Under mpirun every rank meets the same bad input: only rank 0 says so (one line, as always).
static std::ostream& errors() {
  static std::ostringstream quiet;
  for (const char* k : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
    if (const char* v = std::getenv(k); v && std::atoi(v) > 0) return quiet;
  return std::cerr;
}

// The one line printed for an error: a library's lines joined, echoed input cut to a readable
// length.
static std::string error_line(const char* what) {
  return zc::shorten_echo(zc::one_line(what));
}

// Where standard output is the result (a platform, a table, a listing), a write that failed (a full
// disk, /dev/full, a closed descriptor) fails the command: one line, exit status 1. An error
// already reported keeps its own line and status.
static int with_output_checked(int status) {
  errno = 0;
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (!failed || status != 0) return status;
  const int err = errno;
  errors() << "zcube: error: cannot write standard output"
           << (err ? std::string(": ") + std::strerror(err) : std::string()) << "\n";
  return 1;
}

static int run_command(int argc, char** argv);

namespace {

// -q: standard error keeps its error lines ("zcube: error: ...") and drops the rest (progress,
// notes, the host-cost lines), line by line; standard output, the result, is untouched.
class ErrorsOnly : public std::streambuf {
public:
  explicit ErrorsOnly(std::streambuf* to) : to_(to) {}

protected:
  int overflow(int c) override {
    if (c == EOF) return 0;
    line_.push_back(char(c));
    if (c == '\n') {
      if (line_.find("error") != std::string::npos)
        to_->sputn(line_.data(), std::streamsize(line_.size()));
      line_.clear();
    }
    return c;
  }
  int sync() override { return to_->pubsync(); }

private:
  std::streambuf* to_;
  std::string line_;
};

// Takes -q/--quiet out of the arguments after the command; true when it was there.
bool take_quiet(int& argc, char** argv) {
  bool quiet = false;
  int kept = 2;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-q" || a == "--quiet")
      quiet = true;
    else
      argv[kept++] = argv[i];
  }
  argc = std::min(argc, kept);
  return quiet;
}

} // namespace

int main(int argc, char** argv) {
  static ErrorsOnly errors_only(std::cerr.rdbuf());
  if (argc > 2 && take_quiet(argc, argv)) {
    std::cerr.rdbuf(&errors_only);
    setenv("ZCUBE_QUIET", "1", 1); // the progress lines written straight to descriptor 2
  }
  return with_output_checked(run_command(argc, argv));
}

static int run_command(int argc, char** argv) {
  if (argc < 2) {
    usage(std::cerr);
    return 2;
  }
  const std::string cmd = argv[1];
  if (cmd == "--version" || cmd == "version") {
    int major = 0, minor = 0, patch = 0;
    sg_version_get(&major, &minor, &patch);
    std::cout << "zcube " << ZCUBE_VERSION << " (SimGrid " << major << "." << minor << "." << patch
              << ")\n";
    return 0;
  }
  if ((cmd == "--help" || cmd == "-h" || cmd == "help") && argc < 3) {
    usage(std::cout);
    return 0;
  }
  if (cmd == "help" && std::string(argv[2]) == "flags") { // the docs' table of run flags
    std::cout << zc::run_flags_markdown();
    return 0;
  }
  auto& reg = zc::cli::registry();
  // zcube help run: run's own --help.
  const bool help = cmd == "help";
  auto it = reg.find(help ? argv[2] : cmd);
  if (it == reg.end()) {
    std::cerr << "zcube: error: unknown command '" << (help ? argv[2] : cmd)
              << "' (zcube --help lists them; zcube help flags, the run flags)\n";
    return 2;
  }
  std::vector<std::string> args(argv + 2, argv + argc);
  if (help) args = {"--help"};
  zc::set_command_line({argv, argv + argc}); // the provenance every report carries
  try {
    return it->second.run(args);
  } catch (const zc::InputError& e) {
    errors() << "zcube: error: " << error_line(e.what()) << "\n";
    return 2;
  } catch (const zc::UsageError& e) {
    errors() << "zcube: error: " << error_line(e.what()) << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    errors() << "zcube: error: out of host memory\n";
    return 1;
  } catch (const std::exception& e) {
    errors() << "zcube: error: " << error_line(e.what()) << "\n";
    return 1;
  }
}
