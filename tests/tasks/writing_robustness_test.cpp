#include "teaching/tasks/writing_robustness.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "engine/core/asset_paths.hpp"
#include "engine/writing/word_generator.hpp"
#include "teaching/skills/compile_extractor.hpp"
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

// The shipped writing model keeps its letters under the realistic learner's 5 px wobble read through a
// mouse: the targets (F1 >= 0.92, letter->skill agreement >= 0.9), on 40 words of a seed used for
// no choice (200 words at seeds 1, 2, 15, 16 measured 0.95-0.96 and 0.97: docs/skills.md). A retrained model
// that loses them fails here.
TEST(WritingRobustness, TheShippedModelMeetsTheFivePixelWobbleTargets) {
  const CompileExtractor model = CompileExtractor::load(asset_dir() / "models" / "writing.pt", "writing");
  std::vector<WritingCondition> conditions = writing_robustness_conditions();
  conditions.erase(std::remove_if(conditions.begin(), conditions.end(),
                                  [](const WritingCondition& c) { return c.name != "wobble 5 px"; }),
                   conditions.end());
  ASSERT_EQ(conditions.size(), 1u);
  const std::vector<WritingRobustnessRow> rows =
      measure_writing_robustness(model, ClassicDrawerGlyphs::load(), writing::classic_words(40, 21), 21, conditions);
  ASSERT_EQ(rows.size(), 1u);
  const double agreement = static_cast<double>(rows[0].agreeing) / rows[0].letters;
  std::printf("5 px wobble, 40 words of seed 21: F1 %.3f, agreement %.3f\n", rows[0].boundaries.f1(), agreement);
  EXPECT_GE(rows[0].boundaries.f1(), 0.92);
  EXPECT_GE(agreement, 0.9);
}

}  // namespace
}  // namespace sc
