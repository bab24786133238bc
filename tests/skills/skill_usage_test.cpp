#include "teaching/skills/skill_usage.hpp"

#include <gtest/gtest.h>

#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

using test::segments_of;

TEST(SkillUsage, CountsSegmentsStepsAndMeanLengthPerSkill) {
  const SkillUsageSummary u = skill_usage({segments_of({{2, 10}, {5, 4}, {2, 6}}), segments_of({{5, 8}})});
  ASSERT_EQ(u.skills_used(), 2);
  EXPECT_EQ(u.skills[0].skill, 2);
  EXPECT_EQ(u.skills[0].segments, 2);
  EXPECT_EQ(u.skills[0].steps, 16);
  EXPECT_DOUBLE_EQ(u.skills[0].mean_segment_length(), 8.0);
  EXPECT_EQ(u.skills[1].skill, 5);
  EXPECT_DOUBLE_EQ(u.skills[1].mean_segment_length(), 6.0);
  EXPECT_EQ(u.segments, 4);
  EXPECT_DOUBLE_EQ(u.mean_segment_length(), 7.0);
}

TEST(SkillUsage, EmptyInputUsesNoSkills) {
  const SkillUsageSummary u = skill_usage({Segmentation{}});
  EXPECT_EQ(u.skills_used(), 0);
  EXPECT_DOUBLE_EQ(u.mean_segment_length(), 0.0);
  const Json j = to_json(u);
  EXPECT_EQ(j.at("skills_used"), 0);
  EXPECT_TRUE(j.at("per_skill").empty());
}

}  // namespace
}  // namespace sc
