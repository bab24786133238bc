#include "teaching/curricula/adaptive_curriculum.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

Segmentation seq(const std::vector<std::pair<int, int>>& parts) { return test::segments_of(parts); }

// Skills 0 -> 1 -> 2 always go together; 3, 4, 5 form the other scenario family.
CurriculumInputs inputs() {
  CurriculumInputs in;
  for (int i = 0; i < 8; ++i) in.expert_skills.push_back(seq({{0, 4}, {1, 5}, {2, 3}}));
  for (int i = 0; i < 8; ++i) in.expert_skills.push_back(seq({{3, 6}, {4, 6}}));
  for (int i = 0; i < 4; ++i) in.expert_skills.push_back(seq({{4, 5}, {5, 4}, {3, 2}}));
  // Pre-test on experts 0, 8, 16: the learner skips skill 0 (a planted weakness), does the rest.
  std::vector<ExpertiseTrial> pretest = {{0, in.expert_skills[0], seq({{1, 6}, {2, 6}}), -0.6},
                                         {8, in.expert_skills[8], in.expert_skills[8], -0.1},
                                         {16, in.expert_skills[16], in.expert_skills[16], -0.1}};
  in.pretest = estimate_expertise(pretest, 6, 7);
  in.seed = 77;
  return in;
}

// The learner's attempt at an item, with every segment of `missing` left out (a planted weakness).
ExpertiseTrial attempt(const PracticeItem& item, int missing, int id) {
  Segmentation learner;
  for (const auto& s : plan_segmentation(item.material).segments) {
    if (s.skill != missing) learner.segments.push_back(s);
  }
  return practice_trial(item, learner, -0.5, id);
}

TEST(AdaptiveCurriculum, FirstRoundIsIndividualizedOnThePretest) {
  const CurriculumInputs in = inputs();
  const AdaptiveRound r0 = first_adaptive_round(in, CurriculumConfig::parking());
  EXPECT_EQ(r0.diagnosis.ranking.front(), 0);
  ASSERT_FALSE(r0.practice.items.empty());
  EXPECT_EQ(r0.practice.condition, StudyCondition::Adaptive);
  EXPECT_EQ(r0.practice.items[0].target_skills, (std::vector<int>{0}));
  EXPECT_EQ(r0.practice.items[0].material.ngram, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(make_curriculum(StudyCondition::Adaptive, in, CurriculumConfig::parking()).items, r0.practice.items);
}

TEST(AdaptiveCurriculum, RetargetsTowardsAWeaknessPlantedInPractice) {
  const CurriculumInputs in = inputs();
  const CurriculumConfig config = CurriculumConfig::parking();
  std::vector<AdaptiveRound> rounds = {first_adaptive_round(in, config)};
  // In practice the learner now performs skill 0 but never shows skill 1.
  std::vector<ExpertiseTrial> trials;
  for (std::size_t i = 0; i < rounds[0].practice.items.size(); ++i) {
    trials.push_back(attempt(rounds[0].practice.items[i], 1, static_cast<int>(i)));
  }
  const AdaptiveRound r1 = next_round(rounds, trials, in, config);
  EXPECT_TRUE(r1.evidence.penalised(1));
  EXPECT_FALSE(r1.evidence.penalised(0));
  EXPECT_EQ(r1.diagnosis.ranking.front(), 1);
  EXPECT_FALSE(r1.diagnosis.penalised(0));  // the newer evidence replaced the pre-test's penalty
  ASSERT_FALSE(r1.practice.items.empty());
  EXPECT_EQ(r1.practice.items[0].target_skills, (std::vector<int>{1}));

  // Deterministic: the same rounds and trials give the same next round.
  EXPECT_EQ(next_round(rounds, trials, in, config).practice.items, r1.practice.items);

  // Once the learner performs everything, nothing is penalised any more.
  rounds.push_back(r1);
  std::vector<ExpertiseTrial> perfect;
  for (std::size_t i = 0; i < r1.practice.items.size(); ++i)
    perfect.push_back(attempt(r1.practice.items[i], -1, static_cast<int>(i)));
  const AdaptiveRound r2 = next_round(rounds, perfect, in, config);
  for (int m : r2.diagnosis.ranking) EXPECT_FALSE(r2.diagnosis.penalised(m)) << m;
}

TEST(AdaptiveCurriculum, NoPracticeTrialsKeepTheDiagnosis) {
  const CurriculumInputs in = inputs();
  const CurriculumConfig config = CurriculumConfig::parking();
  const std::vector<AdaptiveRound> rounds = {first_adaptive_round(in, config)};
  const AdaptiveRound r1 = next_round(rounds, {}, in, config);
  EXPECT_EQ(r1.diagnosis.ranking.front(), 0);
  EXPECT_THROW(next_round({}, {}, in, config), InputError);
}

}  // namespace
}  // namespace sc
