// Results tables: CSV quoted as RFC 4180 says (commas, quotes, CR and LF in a cell) and read back
// by the tests' reader; Markdown cells escape '|' and keep a row on one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "csv.hpp"
#include "repro/table.hpp"

TEST(Table, CsvQuotesEverySpecialCharacterAndReadsBack) {
  zc::Table t{{"name", "value"}, {}};
  const std::vector<std::string> cells = {"packing,clear", "a \"quoted\" word", "cr\rhere",
                                          "lf\nhere", "plain"};
  for (const auto& c : cells)
    t.add({c, "1"});
  const std::string csv = t.csv();
  EXPECT_NE(csv.find("\"packing,clear\""), std::string::npos);
  EXPECT_NE(csv.find("\"a \"\"quoted\"\" word\""), std::string::npos);
  EXPECT_NE(csv.find("\"cr\rhere\""), std::string::npos);
  std::istringstream in(csv);
  const auto records = zc::test::csv_records(in);
  ASSERT_EQ(records.size(), cells.size() + 1);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    ASSERT_EQ(records[i + 1].size(), 2u) << i;
    EXPECT_EQ(records[i + 1][0], cells[i]);
  }
}

TEST(Table, MarkdownEscapesBarsAndLineBreaks) {
  zc::Table t{{"a|b", "c"}, {}};
  t.add({"x|y", "two\nlines"});
  const std::string md = t.markdown();
  EXPECT_NE(md.find("| a\\|b | c |"), std::string::npos) << md;
  EXPECT_NE(md.find("| x\\|y | two lines |"), std::string::npos) << md;
  EXPECT_EQ(std::count(md.begin(), md.end(), '\n'), 3);
}

TEST(Table, CommittedSelectionTableReadsItsQuotedCells) {
  const auto rows =
      zc::test::read_csv(std::string(ZCUBE_SOURCE_DIR) + "/results/calibration/selection.csv");
  ASSERT_FALSE(rows.empty());
  bool quoted_seen = false;
  for (const auto& r : rows)
    for (const auto& [k, v] : r)
      quoted_seen |= v.find(',') != std::string::npos;
  EXPECT_TRUE(quoted_seen) << "selection.csv holds \"packing,clear\": one cell, not two";
}
