#include "engine/core/error.hpp"

#include <gtest/gtest.h>

namespace sc {

TEST(InputError, NamesWhereAndWhatOnOneLine) {
  InputError e("trial.json", "line 1\nline 2");
  EXPECT_STREQ(e.what(), "trial.json: line 1 line 2");
}

TEST(OneLine, StripsTrailingSpaceAndTabs) { EXPECT_EQ(one_line("a\tb\n"), "a b"); }

// A file name or JSON string with terminal escapes must not drive the user's terminal.
TEST(OneLine, ShowsOtherControlBytesAsText) {
  EXPECT_EQ(one_line("trial\x1b[2J.json"), "trial\\x1b[2J.json");
  EXPECT_EQ(one_line(std::string("a\0b\x7f", 4)), "a\\x00b\\x7f");
  InputError e("bad\x07name.json", "not valid JSON");
  EXPECT_STREQ(e.what(), "bad\\x07name.json: not valid JSON");
}

}  // namespace sc
