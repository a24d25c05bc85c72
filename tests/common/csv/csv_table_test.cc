// The CSV files rlpos-sim writes, read back by column name: rows as wide as the header, errors
// that name the line.
#include "common/csv/csv_table.h"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

namespace rlpos {
namespace {

std::string ErrorOf(const std::string& text) {
  std::istringstream in(text);
  try {
    ReadCsvTable(in);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(CsvTable, ReadsTheHeaderAndEveryRowWithItsLine) {
  std::istringstream in("episode,phase,total_reward\n1,train,0.5\n2,eval,0.7\n");
  const CsvTable table = ReadCsvTable(in);
  EXPECT_EQ(table.header, (std::vector<std::string>{"episode", "phase", "total_reward"}));
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.rows[0].line, 2);
  EXPECT_EQ(table.rows[0].cells, (std::vector<std::string>{"1", "train", "0.5"}));
  EXPECT_EQ(table.rows[1].line, 3);
  EXPECT_EQ(table.rows[1].cells[2], "0.7");
}

TEST(CsvTable, FindsColumnsByName) {
  std::istringstream in("x,y,z\n");
  const CsvTable table = ReadCsvTable(in);
  EXPECT_EQ(table.Column("y"), 1u);
  EXPECT_EQ(table.Find("uav"), std::string::npos);
  try {
    table.Column("uav");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "line 1: no column \"uav\"");
  }
}

TEST(CsvTable, ARowOfAnotherWidthNamesItsLine) {
  EXPECT_EQ(ErrorOf("a,b\n1,2\n1,2,3\n"), "line 3: 3 cells, not 2");
  EXPECT_EQ(ErrorOf("a,b\n1\n"), "line 2: 1 cells, not 2");
  EXPECT_EQ(ErrorOf(""), "empty file");
}

TEST(CsvTable, SplitsAtEveryComma) {
  EXPECT_EQ(SplitCsvLine("1,,3"), (std::vector<std::string>{"1", "", "3"}));
  EXPECT_EQ(SplitCsvLine(""), (std::vector<std::string>{}));
}

}  // namespace
}  // namespace rlpos
