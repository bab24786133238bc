#include "teaching/students/finetune_data.hpp"

#include <algorithm>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

// Eight expert demos over skills 0..4 with 1-D states that encode (demo, step) = 100 * demo + step, so
// every pair can be traced back to the expert step it came from.
FinetuneMaterial toy_material() {
  const std::vector<std::vector<int>> skills = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 4},
                                                {0, 1, 2}, {2, 3, 4}, {0, 1, 4}, {1, 3, 4}};
  FinetuneMaterial m;
  for (std::size_t e = 0; e < skills.size(); ++e) {
    const int length = 4 + static_cast<int>(e % 3);  // segments of 4..6 steps
    m.expert_skills.push_back(test::segments_of(skills[e], length));
    StepSequence s{1, 2, {}, {}};
    for (int t = 0; t < 3 * length; ++t) {
      s.states.push_back(static_cast<float>(100 * e + static_cast<std::size_t>(t)));
      s.actions.push_back(t % 2 ? 0.5f : -0.5f);
      s.actions.push_back(0.0f);
    }
    m.expert_steps.push_back(s);
  }
  // The student misses skills 4 and 3 in every trial: those rank weakest.
  std::vector<ExpertiseTrial> trials;
  for (std::size_t e = 0; e < skills.size(); ++e)
    trials.push_back({static_cast<int>(e), m.expert_skills[e], test::segments_of({0, 1, 2}, 3), -0.5});
  m.diagnosis = estimate_expertise(trials, 5, 3);
  m.num_targets = 3;
  return m;
}

TEST(FinetuneData, EveryConditionGetsExactlyTheRequestedNumberOfPairs) {
  const FinetuneMaterial m = toy_material();
  for (int pairs : {1, 17, 64, 500}) {
    for (StudyCondition c : {StudyCondition::IndDrills, StudyCondition::Drills, StudyCondition::FullTrajectory}) {
      const FinetuneData d = finetune_data(c, m, pairs, 3);
      EXPECT_EQ(d.pairs.size(), pairs) << condition_name(c);
      EXPECT_EQ(d.pairs.state_dim, 1);
      EXPECT_FALSE(d.items.empty());
    }
  }
}

TEST(FinetuneData, PairsAreTheExpertStepsOfTheConditionsMaterialInOrder) {
  const FinetuneMaterial m = toy_material();
  const FinetuneData d = finetune_data(StudyCondition::IndDrills, m, 40, 3);
  std::vector<float> expected;
  for (const PracticeItem& item : d.items)
    for (const DrillSegment& s : item.material.segments)
      for (int t = s.begin; t < s.end; ++t) expected.push_back(static_cast<float>(100 * s.expert + t));
  expected.resize(40);
  EXPECT_EQ(d.pairs.states, expected);
  // Ind. Drills target the diagnosis' weakest skills, each drill contains its target.
  for (const PracticeItem& item : d.items) {
    EXPECT_NE(std::find(m.diagnosis.targets.begin(), m.diagnosis.targets.end(), item.material.target_skill),
              m.diagnosis.targets.end());
    EXPECT_NE(std::find(item.material.ngram.begin(), item.material.ngram.end(), item.material.target_skill),
              item.material.ngram.end());
  }
  // Full Trajectory plays whole demos from their first step.
  const FinetuneData full = finetune_data(StudyCondition::FullTrajectory, m, 40, 3);
  for (const PracticeItem& item : full.items) EXPECT_EQ(item.material.segments.front().begin, 0);
}

TEST(FinetuneData, SameSeedSameDataAndTheDefaultSizeIsOneIndividualizedRound) {
  const FinetuneMaterial m = toy_material();
  EXPECT_EQ(finetune_data(StudyCondition::Drills, m, 50, 9).pairs.states,
            finetune_data(StudyCondition::Drills, m, 50, 9).pairs.states);
  EXPECT_NE(finetune_data(StudyCondition::FullTrajectory, m, 50, 9).pairs.states,
            finetune_data(StudyCondition::FullTrajectory, m, 50, 10).pairs.states);
  // One drill per target (N_drills = 1), each an n-gram of 3 segments of 4..6 steps.
  const int round = individualized_round_pairs(m, 9);
  EXPECT_GE(round, 3 * 3 * 4);
  EXPECT_LE(round, 3 * 3 * 6);
  const FinetuneData d = finetune_data(StudyCondition::IndDrills, m, round, 9);
  ASSERT_EQ(d.items.size(), 3u);
  EXPECT_EQ(d.items[0].steps() + d.items[1].steps() + d.items[2].steps(), round);
}

TEST(FinetuneData, RefusesOtherConditionsAndEmptySizes) {
  const FinetuneMaterial m = toy_material();
  EXPECT_THROW(finetune_data(StudyCondition::Skills, m, 10, 0), InputError);
  EXPECT_THROW(finetune_data(StudyCondition::IndDrills, m, 0, 0), InputError);
  FinetuneMaterial undiagnosed = m;
  undiagnosed.diagnosis = {};
  EXPECT_THROW(individualized_round_pairs(undiagnosed, 0), InputError);
}

}  // namespace
}  // namespace sc
