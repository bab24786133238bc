#include "app/core/fitted_text.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

// One pixel per code point (UTF-8 continuation bytes take none), as a monospaced font would measure.
float code_points(const std::string& s) {
  float n = 0.0f;
  for (char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1.0f : 0.0f;
  return n;
}

TEST(FittedText, TextThatFitsIsKeptWhole) {
  EXPECT_EQ(fitted_to_width("learner", 7.0f, code_points), "learner");
  EXPECT_EQ(fitted_in_middle("trial.json", 10.0f, code_points), "trial.json");
}

TEST(FittedText, AnEndCutKeepsTheLongestBeginningThatFitsWithItsDots) {
  EXPECT_EQ(fitted_to_width("Ada - writing - adaptive", 10.0f, code_points), "Ada - w...");
  EXPECT_EQ(fitted_to_width("abc", 2.0f, code_points), "...");  // nothing fits beside the dots
}

TEST(FittedText, AMiddleCutKeepsBothEndsAndFavoursTheEnd) {
  const std::string name = "a_very_long_recorded_trial_name.json  \xc2\xb7  CompILE writing.pt";
  const std::string cut = fitted_in_middle(name, 30.0f, code_points);
  EXPECT_LE(code_points(cut), 30.0f);
  EXPECT_EQ(cut.substr(0, 2), "a_");
  EXPECT_EQ(cut.substr(cut.size() - 10), "writing.pt");
  EXPECT_NE(cut.find("..."), std::string::npos);
  // The middle dot (2 bytes) is either kept whole or cut whole.
  for (std::size_t i = 0; i < cut.size(); ++i) {
    if (static_cast<unsigned char>(cut[i]) == 0xC2) {
      ASSERT_TRUE(i + 1 < cut.size() && cut[i + 1] == '\xb7');
    }
  }
}

TEST(FittedText, CutsNeverSplitACodePoint) {
  const std::string dots = "\xc2\xb7\xc2\xb7\xc2\xb7\xc2\xb7\xc2\xb7\xc2\xb7";  // six middle dots
  const std::string end = fitted_to_width(dots, 5.0f, code_points);
  EXPECT_EQ(end, "\xc2\xb7\xc2\xb7...");
  const std::string middle = fitted_in_middle(dots, 5.0f, code_points);
  EXPECT_EQ(code_points(middle), 5.0f);
  EXPECT_EQ(middle.size(), 3u + 2u * 2u);  // two whole dots around "..."
}

}  // namespace
}  // namespace sc
