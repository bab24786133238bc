#include "teaching/tasks/writing_robustness.hpp"

#include <gtest/gtest.h>

#include "teaching/skills/time_heuristic_extractor.hpp"

namespace sc {
namespace {

TEST(WritingRobustness, MajoritySkillCountsStepsInTheRange) {
  const Segmentation s{{{3, 0, 10}, {5, 10, 14}, {3, 14, 20}}};
  EXPECT_EQ(majority_skill(s, 8, 15), 5);  // 4 steps of 5, 3 of 3
  EXPECT_EQ(majority_skill(s, 0, 20), 3);
  EXPECT_EQ(majority_skill(s, 20, 20), -1);
}

TEST(WritingRobustness, TheExpertsOwnWordsAgreeFullyAndNoiseIsScored) {
  const TimeHeuristicExtractor equal_slices(8);
  std::vector<WritingCondition> conditions = writing_robustness_conditions();
  ASSERT_EQ(conditions.front().name, "expert gold");
  conditions.resize(3);  // gold, mouse sampling, 5 px wobble: enough to check the bookkeeping
  const std::vector<WritingRobustnessRow> rows =
      measure_writing_robustness(equal_slices, ClassicDrawerGlyphs::load(), {"ab-ct^e", "ba^t"}, 0, conditions);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].letters, 8);  // a b c t e + b a t
  EXPECT_EQ(rows[0].agreeing, 8);
  EXPECT_EQ(rows[0].boundaries.true_positives + rows[0].boundaries.false_negatives, 6 + 3);
  for (const auto& r : rows) {
    EXPECT_EQ(r.letters, 8);
    EXPECT_GE(r.boundaries.f1(), 0.0);
    EXPECT_LE(r.boundaries.f1(), 1.0);
  }
  EXPECT_NE(robustness_table(rows).find("| wobble 5 px |"), std::string::npos);
}

}  // namespace
}  // namespace sc
