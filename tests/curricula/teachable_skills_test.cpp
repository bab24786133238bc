#include "teaching/curricula/teachable_skills.hpp"

#include <gtest/gtest.h>

#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

// Skill 9 is a 1-2 step filler; skill 4 is long once and short twice; skills 0 and 1 are ordinary.
std::vector<Segmentation> pool() {
  return {test::segments_of({{0, 6}, {9, 1}, {1, 7}}), test::segments_of({{1, 5}, {4, 2}, {9, 2}}),
          test::segments_of({{4, 8}, {0, 5}}), test::segments_of({{4, 2}, {1, 6}})};
}

TEST(TeachableSkills, ASkillIsTeachableWhenOneOfItsSegmentsIsLongEnough) {
  EXPECT_TRUE(is_teachable(4, pool(), 5));   // one 8-step segment suffices
  EXPECT_FALSE(is_teachable(9, pool(), 3));  // only 1 and 2 steps
  EXPECT_TRUE(is_teachable(9, pool(), 1));   // min 1: every skill that occurs
  EXPECT_FALSE(is_teachable(7, pool(), 1));  // never occurs
}

TEST(TeachableSkills, FrequencyCountsOnlyLongEnoughSegments) {
  // Long segments (>= 5): skill 1 x3, skill 0 x2, skill 4 x1 (its 2-step ones do not count); 9 left out.
  const auto ranked = teachable_by_frequency(pool(), 5);
  ASSERT_EQ(ranked.size(), 3u);
  EXPECT_EQ(ranked[0], (std::pair<int, int>{1, 3}));
  EXPECT_EQ(ranked[1], (std::pair<int, int>{0, 2}));
  EXPECT_EQ(ranked[2], (std::pair<int, int>{4, 1}));
}

TEST(TeachableSkills, RankingDropsSkillsTooBriefToPractise) {
  ExpertiseEstimate diagnosis;
  diagnosis.ranking = {9, 4, 0, 1};
  EXPECT_EQ(teachable_ranking(diagnosis, pool(), 5), (std::vector<int>{4, 0, 1}));
  EXPECT_EQ(teachable_ranking(diagnosis, pool(), 7), (std::vector<int>{4, 1}));
}

}  // namespace
}  // namespace sc
