#include "engine/core/error.hpp"

#include <gtest/gtest.h>

namespace sc {

TEST(InputError, NamesWhereAndWhatOnOneLine) {
  InputError e("trial.json", "line 1\nline 2");
  EXPECT_STREQ(e.what(), "trial.json: line 1 line 2");
}

TEST(OneLine, StripsTrailingSpaceAndTabs) { EXPECT_EQ(one_line("a\tb\n"), "a b"); }

}  // namespace sc
