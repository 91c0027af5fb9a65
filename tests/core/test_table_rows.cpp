// The rows of a text table: a byte-order mark, blank and comment lines skipped, line numbers kept,
// and the two ways a line splits into cells.
#include <gtest/gtest.h>

#include <sstream>

#include "core/table_rows.h"

using namespace columba;

TEST(TableRows, AByteOrderMarkBlankAndCommentLinesAreSkippedAndLinesCounted) {
  std::istringstream in("\xEF\xBB\xBFwl, UVS\n\n  # a comment\n 300,\t0.5 \n");
  TableRows rows(in, TableRows::Separators::Commas);
  std::vector<std::string> cells;
  ASSERT_TRUE(rows.next(cells));
  EXPECT_EQ(cells, (std::vector<std::string>{"wl", "UVS"}));
  EXPECT_EQ(rows.line(), 1);
  ASSERT_TRUE(rows.next(cells));
  EXPECT_EQ(cells, (std::vector<std::string>{"300", "0.5"}));
  EXPECT_EQ(rows.line(), 4);
  EXPECT_FALSE(rows.next(cells));
  EXPECT_EQ(rows.line(), 4);
}

TEST(TableRows, CommasKeepEmptyFieldsWhereCommasOrWhiteSpaceDropThem) {
  std::istringstream csv("a,,b c,\n"), list("a,,b c,\n");
  std::vector<std::string> cells;
  ASSERT_TRUE(TableRows(csv, TableRows::Separators::Commas).next(cells));
  EXPECT_EQ(cells, (std::vector<std::string>{"a", "", "b c"}));  // a closing comma opens no field
  ASSERT_TRUE(TableRows(list, TableRows::Separators::CommasOrWhiteSpace).next(cells));
  EXPECT_EQ(cells, (std::vector<std::string>{"a", "b", "c"}));
}
