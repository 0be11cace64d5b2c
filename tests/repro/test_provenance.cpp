// repro/provenance: what every report, golden file and results README says of where it came from,
// and what a committed file must leave out to be rewritten bit for bit on another checkout.
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "repro/provenance.hpp"

using namespace zc;

TEST(Provenance, NamesSchemaVersionsCommitAndCommandLine) {
  set_command_line({"/some/where/build/zcube", "run", "--nodes", "4"});
  const auto p = provenance();
  EXPECT_EQ(p["schema_version"], kSchemaVersion);
  EXPECT_TRUE(
      std::regex_match(p["zcube_version"].get<std::string>(), std::regex(R"(\d+\.\d+\.\d+)")))
      << p.dump();
  EXPECT_TRUE(
      std::regex_match(p["simgrid_version"].get<std::string>(), std::regex(R"(3\.\d+\.\d+)")))
      << p.dump();
  ASSERT_TRUE(p.contains("zcube_commit"));
  EXPECT_FALSE(p["zcube_commit"].get<std::string>().empty());
  EXPECT_EQ(p["command_line"], nlohmann::json({"zcube", "run", "--nodes", "4"}));
}

// A committed file: no commit, no path of this machine, no core count.
TEST(Provenance, CommittedFileIsTheSameOnEveryCheckout) {
  const std::string cwd = std::filesystem::current_path().string();
  set_command_line({"./build/zcube", "regress", "--jobs", "7", "--write", cwd + "/tests/golden",
                    "--runs=" + cwd + "/tests/golden/runs.json", "--jobs=3", "/elsewhere/x"});
  const auto p = provenance(ProvenanceFor::committed_file);
  EXPECT_FALSE(p.contains("zcube_commit"));
  EXPECT_EQ(p["command_line"], nlohmann::json({"zcube", "regress", "--write", "tests/golden",
                                               "--runs=tests/golden/runs.json", "/elsewhere/x"}));
  EXPECT_EQ(p["schema_version"], kSchemaVersion);
}

TEST(Provenance, FilesWithoutItAreSchemaZero) {
  EXPECT_EQ(schema_version_of(nlohmann::json::object()), 0);
  EXPECT_EQ(schema_version_of({{"provenance", "text"}}), 0);
  EXPECT_EQ(schema_version_of(nlohmann::json::array()), 0);
  EXPECT_EQ(schema_version_of({{"provenance", provenance()}}), kSchemaVersion);
  EXPECT_EQ(provenance_text(nullptr), "no provenance (schema 0)");
  EXPECT_NE(provenance_text(provenance()).find("SimGrid 3."), std::string::npos);
}

TEST(Provenance, AppendedToAReadmeOnce) {
  const auto path = std::filesystem::temp_directory_path() / "zcube-test-provenance-README.md";
  std::ofstream(path) << "# Results\n";
  set_command_line({"zcube", "reproduce", "--jobs", "2"});
  append_provenance(path.string());
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  std::filesystem::remove(path);
  EXPECT_NE(text.str().find("## Provenance"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("`zcube reproduce`"), std::string::npos) << text.str();
  EXPECT_EQ(text.str().find("commit"), std::string::npos) << text.str();
}
