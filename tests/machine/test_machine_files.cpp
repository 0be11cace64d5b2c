// machines/*.json and machines/cpu/*.json: every data file is built in, the worked example of
// docs/adding-a-machine.md is a machine, and a broken file is one line naming the file and field.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "machine/cpu_model.hpp"
#include "machine/machine.hpp"
#include "machine/machine_file.hpp"
#include "util/error.hpp"

using namespace zc;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> json_stems(const fs::path& dir) {
  std::vector<std::string> v;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".json" && e.path().stem() != "operations")
      v.push_back(e.path().stem().string());
  std::sort(v.begin(), v.end());
  return v;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The first ```json block of the document.
std::string json_block(const std::string& doc) {
  const std::string open = "```json\n";
  const auto from = doc.find(open);
  if (from == std::string::npos) return "";
  const auto to = doc.find("```", from + open.size());
  return doc.substr(from + open.size(), to - from - open.size());
}

const char* kGood = R"({
  "name": "mini", "description": "a test machine", "docs": "here", "cpu": "i80386",
  "memory_bytes": {"value": 1048576, "source": "s"},
  "os_resident_bytes": {"value": 0, "source": "s"},
  "network": {
    "switching": {"value": "circuit", "source": "s"},
    "startup_short_s": {"value": 1e-4, "source": "s"},
    "startup_long_s": {"value": 2e-4, "source": "s"},
    "short_max_bytes": {"value": 100, "source": "s"},
    "bandwidth_Bps": {"value": 2e6, "source": "s"},
    "per_hop_s": {"value": 1e-5, "source": "s"},
    "host_startup_s": {"value": 1e-3, "source": "s"},
    "host_per_byte_s": {"value": 1e-6, "source": "s"}
  }
})";

// kGood with `from` replaced by `to`: the error names the file and `field`.
void expect_refused(const std::string& from, const std::string& to, const std::string& field) {
  std::string text = kGood;
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  try {
    parse_machine_file("machines/mini.json", text, cpu_names());
    ADD_FAILURE() << "accepted: " << to;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("machines/mini.json: ", 0), 0u) << what;
    EXPECT_NE(what.find(field), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

} // namespace

TEST(MachineFiles, EveryDataFileIsBuiltIn) {
  const fs::path root = ZCUBE_SOURCE_DIR;
  EXPECT_EQ(json_stems(root / "machines"), machine_names());
  EXPECT_EQ(json_stems(root / "machines" / "cpu"), cpu_names());
  for (const auto& name : cpu_names())
    EXPECT_EQ(cpu_model(name).name, name);
}

TEST(MachineFiles, UnknownNamesAreListedFromTheRegistry) {
  try {
    machine_spec("nope");
    ADD_FAILURE();
  } catch (const UsageError& e) {
    for (const auto& name : machine_names())
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
  try {
    cpu_model("nope");
    ADD_FAILURE();
  } catch (const UsageError& e) {
    for (const auto& name : cpu_names())
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
}

TEST(MachineFiles, TheWorkedExampleOfTheDocsIsAMachine) {
  const std::string text =
      json_block(read(fs::path(ZCUBE_SOURCE_DIR) / "docs" / "adding-a-machine.md"));
  ASSERT_FALSE(text.empty());
  const MachineSpec m = parse_machine_file("machines/ipsc860-16m.json", text, cpu_names());
  const MachineSpec& base = machine_spec("ipsc860");
  EXPECT_EQ(m.memory_bytes, 2 * base.memory_bytes);
  EXPECT_EQ(m.cpu, base.cpu);
  EXPECT_EQ(m.net.startup_short_s, base.net.startup_short_s);
  EXPECT_EQ(m.net.startup_long_s, base.net.startup_long_s);
  EXPECT_EQ(m.net.per_byte_s, base.net.per_byte_s);
  EXPECT_EQ(m.net.switching, base.net.switching);
}

TEST(MachineFiles, AGoodFileReadsAsWritten) {
  const MachineSpec m = parse_machine_file("machines/mini.json", kGood, cpu_names());
  EXPECT_EQ(m.name, "mini");
  EXPECT_EQ(m.net.per_byte_s, 1 / 2e6);
  EXPECT_EQ(m.net.startup_long_s, 2e-4);
  EXPECT_EQ(m.net.both_ways_Bps, 0);
}

TEST(MachineFiles, ABrokenFileIsOneLineNamingFileAndField) {
  expect_refused(R"("name": "mini")", R"("name": "maxi")", "'name'");
  expect_refused(R"("cpu": "i80386")", R"("cpu": "z80")", "'cpu'");
  expect_refused(R"("docs": "here", )", "", "'docs'");
  expect_refused(R"("startup_short_s")", R"("startup_shrt_s")", "'network.startup_shrt_s'");
  expect_refused(R"({"value": 1e-4, "source": "s"})", R"({"value": 1e-4})",
                 "'network.startup_short_s.source'");
  expect_refused(R"({"value": 2e-4, "source": "s"})", R"({"value": -2e-4, "source": "s"})",
                 "'network.startup_long_s.value'");
  expect_refused(R"({"value": 2e6, "source": "s"})", R"({"value": "2MBps", "source": "s"})",
                 "'network.bandwidth_Bps.value'");
  expect_refused(R"("bandwidth_Bps")",
                 R"("per_byte_s": {"value": 1, "source": "s"}, "bandwidth_Bps")",
                 "'network.per_byte_s'");
  expect_refused(R"({"value": "circuit", "source": "s"})",
                 R"({"value": "wormhole", "source": "s"})", "'network.switching.value'");
  expect_refused(R"({"value": 0, "source": "s"})", R"({"value": 2097152, "source": "s"})",
                 "'os_resident_bytes.value'");
  expect_refused("\"memory_bytes\"", "\"memory\"", "'memory'");
  expect_refused("{\n  \"name\"", "[\n  \"name\"", "not JSON");
}
