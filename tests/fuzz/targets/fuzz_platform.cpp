// libFuzzer target: platform files, the way zcube run --machine FILE.xml reads them
// (src/sim/platform_load.cpp): zcube's grammar and route checks and its trial load in a child of
// its own, SimGrid's parser, then read_platform's checks of every figure and route. An input may
// start with lines of SimGrid settings ("--cfg=name:value", "--log=..."), checked as zcube run
// checks them (sim/simgrid_args.hpp) and, when accepted, given to the engine that loads the file.
// SimGrid allows one engine per process and aborts the process on some input it rejects
// (xbt_assert), so every input is loaded in a forked child; a child that dies (signal, sanitizer
// report) or throws anything but InputError/UsageError is a finding, reported by aborting the
// parent. The child copies its coverage counters back before it exits, so libFuzzer's guidance sees
// the parser and the checks as if they had run in-process.
#include <elf.h>
#include <fcntl.h>
#include <link.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz_common.hpp"
#include "sim/platform_load.hpp"
#include "sim/simgrid_args.hpp"

namespace {

// The inline 8-bit counters of -fsanitize=fuzzer, found as the section __sancov_cntrs of this
// executable (naming its __start_/__stop_ symbols in code breaks libFuzzer's own registration).
struct Counters {
  std::uint8_t* begin = nullptr;
  std::size_t size = 0;
};

int main_program_bias(dl_phdr_info* info, std::size_t, void* out) {
  *static_cast<std::uintptr_t*>(out) = info->dlpi_addr; // the first object is the executable
  return 1;
}

Counters find_counters() {
  std::ifstream f("/proc/self/exe", std::ios::binary);
  std::vector<char> elf((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const auto* eh = reinterpret_cast<const Elf64_Ehdr*>(elf.data());
  const auto* sh = reinterpret_cast<const Elf64_Shdr*>(elf.data() + eh->e_shoff);
  const char* names = elf.data() + sh[eh->e_shstrndx].sh_offset;
  std::uintptr_t bias = 0;
  dl_iterate_phdr(main_program_bias, &bias);
  for (int i = 0; i < eh->e_shnum; ++i)
    if (std::strcmp(names + sh[i].sh_name, "__sancov_cntrs") == 0)
      return {reinterpret_cast<std::uint8_t*>(bias + sh[i].sh_addr), std::size_t(sh[i].sh_size)};
  std::abort();
}

const Counters& counters() {
  static const Counters c = find_counters();
  return c;
}

std::size_t counters_size() {
  return counters().size;
}

// Shared with the children: their counters after loading.
std::uint8_t* shared_counters() {
  static std::uint8_t* p = [] {
    void* m =
        mmap(nullptr, counters_size(), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (m == MAP_FAILED) std::abort();
    return static_cast<std::uint8_t*>(m);
  }();
  return p;
}

// The leading "--cfg=..." and "--log=..." lines of an input, and the rest (the platform).
std::vector<std::string> split_settings(std::string& text) {
  std::vector<std::string> settings;
  while (text.starts_with("--cfg=") || text.starts_with("--log=")) {
    const auto nl = text.find('\n');
    settings.push_back(text.substr(0, nl));
    text = nl == std::string::npos ? "" : text.substr(nl + 1);
  }
  return settings;
}

[[noreturn]] void load_in_child(const std::string& path, const std::vector<std::string>& settings) {
  const int null = open("/dev/null", O_WRONLY);
  dup2(null, STDOUT_FILENO);
  std::vector<std::string> args = {"fuzz_platform", "--log=root.thres:critical"};
  std::vector<char*> argv;
  int rc = 0;
  try {
    zc::check_simgrid_args(settings); // what zcube run refuses never reaches the engine
    args.insert(args.end(), settings.begin(), settings.end());
  } catch (const zc::UsageError&) {
  }
  for (auto& a : args)
    argv.push_back(a.data());
  int argc = int(argv.size());
  try {
    zc::check_platform_file(path); // as a run does: before the engine, with its trial load
    zc::declare_platform_flags();
    simgrid::s4u::Engine e(&argc, argv.data());
    zc::load_platform_file(e, path);
    zc::read_platform(e, path);
  } catch (const zc::InputError&) {
  } catch (const zc::UsageError&) {
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "fuzz_platform: not an InputError: %s\n", ex.what());
    rc = 3;
  }
  std::memcpy(shared_counters(), counters().begin, counters_size());
  _exit(rc);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  const std::vector<std::string> settings = split_settings(text);
  const std::string path = zc::fuzz::write_input(
      "in.xml", reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  std::uint8_t* shared = shared_counters();
  std::memset(shared, 0, counters_size());
  const pid_t pid = fork();
  if (pid < 0) std::abort();
  if (pid == 0) load_in_child(path, settings);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  for (std::size_t i = 0; i < counters_size(); ++i) // saturating, like the counters themselves
    counters().begin[i] = std::uint8_t(std::min(255, counters().begin[i] + shared[i]));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "fuzz_platform: loading the platform %s %d\n",
                 WIFSIGNALED(status) ? "died of signal" : "exited with status",
                 WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
    std::abort();
  }
  return 0;
}
