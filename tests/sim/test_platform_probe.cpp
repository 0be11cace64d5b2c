// sim/platform_probe: what SimGrid ends the process on while loading a platform (an abort, a crash)
// becomes one InputError naming the file and SimGrid's reason; the test process lives on. The files
// here skip zcube's own checks (sim/platform_grammar), which refuse them first in a run.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "machine/machine.hpp"
#include "machine/platform_xml.hpp"
#include "machine/topology.hpp"
#include "sim/platform_probe.hpp"
#include "util/error.hpp"

namespace zc {
namespace {

class ProbeFile {
public:
  explicit ProbeFile(const std::string& text)
      : path_((std::filesystem::temp_directory_path() /
               ("zcube-test-probe-" + std::to_string(::getpid()) + "-" + std::to_string(serial_++) +
                ".xml"))
                  .string()) {
    std::ofstream(path_) << text;
  }
  ~ProbeFile() { std::filesystem::remove(path_); }
  const std::string& path() const { return path_; }

private:
  static inline int serial_ = 0;
  std::string path_;
};

std::string probe_refusal(const std::string& text) {
  const ProbeFile f(text);
  try {
    probe_platform_file(f.path(), {});
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), f.path());
    return e.reason();
  }
  return "";
}

std::string probe_twice(const std::string& xml, const std::string& line) {
  std::string x = xml;
  const auto at = x.find(line);
  EXPECT_NE(at, std::string::npos) << line;
  x.insert(at, line);
  return x;
}

const std::string probe_ring = platform_xml(machine_spec("volvox"), 4, Topology::Ring);

TEST(PlatformProbe, AFileZcubeWritesLoads) {
  EXPECT_EQ(probe_refusal(probe_ring), "");
  EXPECT_EQ(probe_refusal(platform_xml(machine_spec("ipsc860"), 8, Topology::Cube)), "");
}

TEST(PlatformProbe, SimGridsAbortIsAnErrorWithSimGridsReason) {
  // SimGrid's xbt_die: "Link 'ch-0-1' declared several times in the platform."
  const std::string why = probe_refusal(probe_twice(
      probe_ring, "      <link id=\"ch-0-1\" bandwidth=\"1.7MBps\" latency=\"0s\"/>\n"));
  EXPECT_NE(why.find("ch-0-1"), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;
}

TEST(PlatformProbe, SimGridsCrashIsAnError) {
  // A route given twice crashed SimGrid (SIGSEGV in sg_platf_new_route).
  const auto from = probe_ring.find("      <route ");
  const std::string route = probe_ring.substr(from, probe_ring.find('\n', from) + 1 - from);
  const std::string why = probe_refusal(probe_twice(probe_ring, route));
  EXPECT_NE(why, "");
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;
}

TEST(PlatformProbe, ZcubesOwnReadingErrorsComeBackAsTheyAre) {
  std::string x = probe_ring;
  x.replace(x.find("zcube.machine"), 13, "zcube.machina");
  EXPECT_NE(probe_refusal(x).find("not a zcube platform"), std::string::npos) << probe_refusal(x);
}

} // namespace
} // namespace zc
