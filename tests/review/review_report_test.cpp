// trials.csv cells: RFC 4180 quoting, and no cell a spreadsheet would run as a formula (a gamepad may
// report any name, e.g. =HYPERLINK(...)).
#include "teaching/review/review_report.hpp"

#include <gtest/gtest.h>

namespace sc::review {
namespace {

TEST(ReviewReport, CsvFieldsQuoteSeparatorsAndQuotes) {
  EXPECT_EQ(csv_field("keyboard"), "keyboard");
  EXPECT_EQ(csv_field("pad, left"), "\"pad, left\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field(""), "");
}

TEST(ReviewReport, CsvFieldsNeverStartAFormula) {
  EXPECT_EQ(csv_field("=HYPERLINK(\"http://x\",\"y\")"), "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\"");
  EXPECT_EQ(csv_field("+1"), "\"'+1\"");
  EXPECT_EQ(csv_field("-2+3"), "\"'-2+3\"");
  EXPECT_EQ(csv_field("@SUM(A1)"), "\"'@SUM(A1)\"");
  EXPECT_EQ(csv_field("\tcmd"), "\"'\tcmd\"");
  EXPECT_EQ(csv_field("\rcmd"), "\"'\rcmd\"");
  EXPECT_EQ(csv_field("pad=1"), "pad=1");  // only the first character matters
}

}  // namespace
}  // namespace sc::review
