#include "teaching/expertise/latest_evidence.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

Segmentation two_step_segments(const std::vector<int>& skills) { return test::segments_of(skills, 2); }

TEST(LatestEvidenceExpertise, NewerEvidenceReplacesOlderPerSkill) {
  // Pre-test: skill 0 missed (weakest), skill 1 missed later in the sequence, skill 2 fine.
  const ExpertiseEstimate pretest =
      estimate_expertise({{0, two_step_segments({0, 1, 2}), two_step_segments({2}), -1.0},
                          {1, two_step_segments({1, 2}), two_step_segments({1, 2}), -1.0}},
                         4, 4);
  EXPECT_EQ(pretest.ranking.front(), 0);
  // Practice round: skill 0 now performed, skill 2 missed; skill 1 not practised.
  const ExpertiseEstimate practice =
      estimate_expertise({{0, two_step_segments({0, 2}), two_step_segments({0}), -0.8}}, 4, 4);
  const ExpertiseEstimate merged = latest_evidence_expertise({pretest, practice}, 4);
  EXPECT_EQ(merged.expertise[0], 0.0);              // latest: practised without a miss
  EXPECT_DOUBLE_EQ(merged.expertise[1], -0.5 / 2);  // kept from the pre-test, per occurrence (2)
  EXPECT_DOUBLE_EQ(merged.expertise[2], -0.4);      // latest: -0.8 / 2 at position 2, once
  EXPECT_EQ(merged.occurrences[2], 1);
  EXPECT_EQ(merged.contributions[2].size(), 1u);
  EXPECT_EQ(merged.ranking, (std::vector<int>{2, 1, 0}));  // skill 3 never seen: not ranked
}

TEST(LatestEvidenceExpertise, SingleRoundKeepsTheOrderOfMeans) {
  const ExpertiseEstimate only =
      estimate_expertise({{0, two_step_segments({0, 1}), two_step_segments({}), -1.0}}, 2, 2);
  const ExpertiseEstimate merged = latest_evidence_expertise({only}, 1);
  EXPECT_EQ(merged.targets, (std::vector<int>{0}));
  EXPECT_TRUE(latest_evidence_expertise({}, 3).ranking.empty());
}

TEST(LatestEvidenceExpertise, RoundsMustAgreeOnTheSkillCount) {
  const ExpertiseEstimate a = estimate_expertise({}, 3, 1);
  const ExpertiseEstimate b = estimate_expertise({}, 4, 1);
  EXPECT_THROW(latest_evidence_expertise({a, b}, 1), InputError);
}

}  // namespace
}  // namespace sc
