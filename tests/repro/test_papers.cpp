// repro/papers: the registry of the papers `zcube reproduce` knows.
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "repro/papers.hpp"

using namespace zc;

TEST(Papers, NamesAndAliasesDesignateOnePaperEach) {
  std::set<std::string> seen;
  for (const auto& p : papers()) {
    EXPECT_FALSE(p.description.empty()) << p.name;
    EXPECT_NE(p.plan, nullptr) << p.name;
    EXPECT_EQ(find_paper(p.name), &p);
    for (const auto& a : p.aliases)
      EXPECT_EQ(find_paper(a), &p) << a;
  }
  for (const auto& n : paper_names_and_aliases())
    EXPECT_TRUE(seen.insert(n).second) << n << " twice";
  EXPECT_EQ(find_paper("all"), nullptr);
  EXPECT_EQ(find_paper("nope"), nullptr);
}

TEST(Papers, TheFourOfTheResultsInTheirOrder) {
  EXPECT_EQ(paper_names_text(), "kurc, charles, blazek, compositing");
  EXPECT_EQ(find_paper("charles95")->name, "charles");
  EXPECT_EQ(find_paper("blazek91")->name, "blazek");
}

TEST(Papers, EachPaperHasItsAlgorithmsFolderOrIsAStudy) {
  const std::filesystem::path algo = std::filesystem::path(ZCUBE_SOURCE_DIR) / "src" / "algo";
  for (const auto& p : papers()) {
    if (p.name == "compositing") continue; // the study of every paper's compositing (sort_last/)
    EXPECT_TRUE(std::filesystem::is_directory(algo / p.name)) << p.name;
  }
}
