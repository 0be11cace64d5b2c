#include "sim/platform_load.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include <xbt/config.hpp>

#include "machine/clock_limits.hpp"
#include "machine/platform_xml.hpp"
#include "machine/units.hpp"
#include "run/what_if.hpp"
#include "sim/platform_grammar.hpp"
#include "sim/platform_probe.hpp"
#include "sim/platform_routes.hpp"
#include "util/error.hpp"
#include "util/error_text.hpp"
#include "util/input_file.hpp"

namespace zc {

namespace sg = simgrid::s4u;

// Files written before the start-up became a host property set smpi/or in <config>.
void declare_platform_flags() {
  static bool declared = false;
  if (declared) return;
  declared = true;
  simgrid::config::declare_flag<std::string>(
      kStartupConfig, "Receive overhead of SMPI, read by zcube as the message start-up", "0:0:0");
}

bool is_duplex_link(const std::string& name) {
  return name.rfind(kDuplexLinkPrefix, 0) == 0;
}

namespace {

void load(sg::Engine& e, const std::string& path, const std::string& label) {
  try {
    e.load_platform(path);
  } catch (const std::exception& ex) {
    throw InputError(label, 0, "cannot load platform: " + one_line(ex.what()));
  }
}

} // namespace

void load_platform_text(sg::Engine& e, const std::string& xml, const std::string& label) {
  // An anonymous in-memory file: nothing is left behind whatever happens to the run.
  const int fd = memfd_create("zcube-platform", MFD_CLOEXEC);
  if (fd < 0) throw std::runtime_error("memfd_create failed for " + label);
  const bool written = ::write(fd, xml.data(), xml.size()) == ssize_t(xml.size());
  if (!written) {
    ::close(fd);
    throw std::runtime_error("cannot write the platform of " + label);
  }
  try {
    load(e, "/proc/self/fd/" + std::to_string(fd), label);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
}


namespace {

// The platform files this process has checked, by path: their text and <config> settings. A
// batch's parent checks each file once before it forks its simulations (check_platform_file), and
// each forked simulation, finding the same text under the same path, skips the checks and the
// trial load (a calibration step runs twenty points on one file).
struct CheckedFile {
  std::string text;
  std::vector<std::string> settings; // "--cfg=key:value"
};

std::map<std::string, CheckedFile>& checked_files() {
  static std::map<std::string, CheckedFile> files;
  return files;
}

// Far larger than any platform zcube writes (a 1024-node Volvox ring is 0.5 MB).
constexpr std::uintmax_t kMaxPlatformBytes = 64u << 20;

} // namespace

void check_platform_file(const std::string& path) {
  check_input_file(path);
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) > kMaxPlatformBytes)
    throw InputError(path, 0, "larger than 64 MiB: not a platform zcube models");
  std::ifstream f(path);
  std::stringstream text;
  text << f.rdbuf();
  if (!f) throw InputError(path, 0, "cannot read the file");
  std::string xml = text.str();
  const auto known = checked_files().find(path);
  if (known != checked_files().end() && known->second.text == xml) return;
  CheckedFile checked;
  for (const auto& [key, value] : check_platform_grammar(xml, path))
    checked.settings.push_back("--cfg=" + key + ":" + value);
  check_declared_routes(xml, path);
  // SimGrid allows one engine a process: a process that has one cannot try the file in a child.
  if (!sg::Engine::is_initialized()) probe_platform_file(path, checked.settings);
  checked.text = std::move(xml);
  checked_files()[path] = std::move(checked);
}

std::vector<std::string> platform_file_settings(const std::string& path) {
  check_platform_file(path);
  return checked_files().at(path).settings;
}

void load_platform_file(sg::Engine& e, const std::string& path) {
  check_platform_file(path);
  load(e, path, path);
}

void apply_what_ifs(const WhatIfs& w, PlatformModel& m, sg::Engine& e) {
  MachineFigures f{m.machine, m.net, m.memory, 1.0};
  apply_what_ifs(w, f);
  m.net = f.net;
  m.memory = f.memory_bytes;
  if (f.cpu_factor != 1.0)
    for (auto& c : m.cost)
      c = c.scaled(f.cpu_factor);
  const auto& n = m.net;
  for (sg::Link* l : e.get_all_links()) {
    const std::string name = l->get_name();
    if (name == "__loopback__") continue;
    if (is_duplex_link(name)) {
      l->set_bandwidth(n.both_ways_Bps);
      l->set_latency(0);
      continue;
    }
    const bool host = name == kHostUpLink || name == kHostDownLink;
    const double per_byte = host ? n.host_per_byte_s : n.per_byte_s;
    l->set_bandwidth(per_byte > 0 ? 1.0 / per_byte : 1e15);
    l->set_latency(0);
  }
}

} // namespace zc
