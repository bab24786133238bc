#include "teaching/sessions/session_summary.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sc {
namespace {

SkillChange change(double before, double after) {
  SkillChange c;
  c.before = before;
  c.after = after;
  return c;
}

TEST(SkillTrend, NoMistakeBeforeOrAfterIsNotAnImprovement) {
  EXPECT_EQ(skill_trend(change(0.0, 0.0)), SkillTrend::no_mistake);
  EXPECT_EQ(skill_trend(change(-0.004, 0.0)), SkillTrend::no_mistake);  // shown as 0.00 -> 0.00
  EXPECT_EQ(std::string(to_string(SkillTrend::no_mistake)), "no mistake");
}

TEST(SkillTrend, ComparesTheValuesAsShownToTwoDecimals) {
  EXPECT_EQ(skill_trend(change(-0.201, -0.199)), SkillTrend::same);  // both shown as -0.20
  EXPECT_EQ(skill_trend(change(-0.26, -0.20)), SkillTrend::better);
  EXPECT_EQ(skill_trend(change(-0.19, 0.0)), SkillTrend::better);
  EXPECT_EQ(skill_trend(change(0.0, -0.22)), SkillTrend::worse);
  EXPECT_EQ(std::string(to_string(SkillTrend::worse)), "worse");
}

}  // namespace
}  // namespace sc
