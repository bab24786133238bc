#include "teaching/expertise/expertise_estimation.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "tests/support/segmentation_builders.hpp"

namespace sc {
namespace {

Segmentation seq(const std::vector<int>& skills) { return test::segments_of(skills, 3); }

ExpertiseTrial trial(int scenario, const std::vector<int>& expert, const std::vector<int>& student, double reward) {
  return {scenario, seq(expert), seq(student), reward};
}

TEST(ExpertiseEstimation, StudentIdenticalToExpertIsNeverPenalised) {
  const std::vector<ExpertiseTrial> trials = {trial(0, {1, 2, 3}, {1, 2, 3}, -0.4), trial(1, {3, 4}, {3, 4}, -0.9)};
  const ExpertiseEstimate e = estimate_expertise(trials, 6, 7);
  for (int m = 0; m < 6; ++m) {
    EXPECT_EQ(e.expertise[static_cast<std::size_t>(m)], 0.0) << m;
    EXPECT_TRUE(e.contributions[static_cast<std::size_t>(m)].empty()) << m;
    EXPECT_FALSE(e.penalised(m)) << m;
  }
  // All seen skills tie at 0: the one the expert used most (3, twice) first, then by id; 0 and 5 unseen.
  EXPECT_EQ(e.ranking, (std::vector<int>{3, 1, 2, 4}));
  EXPECT_EQ(e.targets, e.ranking);
}

TEST(ExpertiseEstimation, MissingSkillsWeighOneOverTheirOneBasedPosition) {
  // The paper's pseudocode starts j at 0 (division by zero); the first skill must weigh 1, then 1/2, 1/3.
  const ExpertiseEstimate e = estimate_expertise({trial(7, {4, 5, 0}, {2}, -0.6)}, 6, 2);
  EXPECT_DOUBLE_EQ(e.expertise[4], -0.6);
  EXPECT_DOUBLE_EQ(e.expertise[5], -0.3);
  EXPECT_DOUBLE_EQ(e.expertise[0], -0.2);
  ASSERT_EQ(e.contributions[5].size(), 1u);
  EXPECT_EQ(e.contributions[5][0], (ExpertiseContribution{0, 7, 2, -0.6, 0.3}));
  EXPECT_EQ(e.targets, (std::vector<int>{4, 5}));
  EXPECT_TRUE(std::isfinite(e.expertise[4]));
}

TEST(ExpertiseEstimation, PresentSkillsAreNotPenalisedWhereverTheStudentUsesThem) {
  // Order and position in the student's sequence do not matter, only membership.
  const ExpertiseEstimate e = estimate_expertise({trial(0, {1, 2, 3}, {3, 1}, -1.0)}, 4, 4);
  EXPECT_EQ(e.expertise[1], 0.0);
  EXPECT_EQ(e.expertise[3], 0.0);
  EXPECT_DOUBLE_EQ(e.expertise[2], -0.5);
  EXPECT_EQ(e.ranking.front(), 2);
}

TEST(ExpertiseEstimation, RepeatedExpertSkillsArePenalisedPerOccurrence) {
  const ExpertiseEstimate e = estimate_expertise({trial(0, {2, 3, 2}, {3}, -1.0)}, 4, 1);
  EXPECT_DOUBLE_EQ(e.expertise[2], -(1.0 + 1.0 / 3.0));
  ASSERT_EQ(e.contributions[2].size(), 2u);
  EXPECT_EQ(e.contributions[2][0].position, 1);
  EXPECT_EQ(e.contributions[2][1].position, 3);
  EXPECT_EQ(e.occurrences[2], 2);
}

TEST(ExpertiseEstimation, SumsOverScenariosAndScalesWithReward) {
  const std::vector<ExpertiseTrial> trials = {trial(3, {0, 1}, {0}, -0.2), trial(9, {1, 0}, {0}, -0.8)};
  const ExpertiseEstimate e = estimate_expertise(trials, 2, 2);
  EXPECT_DOUBLE_EQ(e.expertise[1], -(0.2 / 2 + 0.8 / 1));
  ASSERT_EQ(e.contributions[1].size(), 2u);
  EXPECT_EQ(e.contributions[1][0].trial, 0);
  EXPECT_EQ(e.contributions[1][0].scenario, 3);
  EXPECT_EQ(e.contributions[1][1].trial, 1);
  EXPECT_EQ(e.contributions[1][1].scenario, 9);
  EXPECT_EQ(e.ranking, (std::vector<int>{1, 0}));
}

TEST(ExpertiseEstimation, TiesBreakByExpertUseThenSkillId) {
  // 2 and 4 both lose exactly 0.5; 4 occurs more often in the expert sequences, so it ranks first.
  const std::vector<ExpertiseTrial> trials = {trial(0, {4, 2}, {4}, -1.0), trial(1, {4, 2}, {2}, -0.5),
                                              trial(2, {1, 3, 4}, {1, 3, 4}, -0.5)};
  const ExpertiseEstimate e = estimate_expertise(trials, 5, 3);
  EXPECT_DOUBLE_EQ(e.expertise[2], -0.5);
  EXPECT_DOUBLE_EQ(e.expertise[4], -0.5);
  EXPECT_EQ(e.ranking, (std::vector<int>{4, 2, 1, 3}));  // 1 and 3: E = 0, once each -> by id
  EXPECT_EQ(e.targets, (std::vector<int>{4, 2, 1}));
}

TEST(ExpertiseEstimation, ZeroRewardRecordsTheMissButCostsNothing) {
  const ExpertiseEstimate e = estimate_expertise({trial(0, {0, 1}, {0}, 0.0)}, 2, 2);
  EXPECT_EQ(e.contributions[1].size(), 1u);
  EXPECT_FALSE(e.penalised(1));
}

TEST(ExpertiseEstimation, RejectsBadInput) {
  EXPECT_THROW(estimate_expertise({trial(0, {0}, {0}, 0.1)}, 2, 1), InputError);
  EXPECT_THROW(estimate_expertise({trial(0, {0}, {0}, std::numeric_limits<double>::quiet_NaN())}, 2, 1), InputError);
  EXPECT_THROW(estimate_expertise({trial(0, {0, 5}, {0}, -1.0)}, 2, 1), InputError);
  EXPECT_THROW(estimate_expertise({trial(0, {0}, {-1}, -1.0)}, 2, 1), InputError);
  EXPECT_THROW(estimate_expertise({}, 0, 1), InputError);
  EXPECT_THROW(estimate_expertise({}, 2, -1), InputError);
  try {
    estimate_expertise({trial(4, {0}, {0}, 0.5)}, 2, 1);
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("scenario 4"), std::string::npos) << err.what();
  }
}

TEST(ExpertiseEstimation, NonPositiveRewardMapsScores) {
  EXPECT_DOUBLE_EQ(non_positive_reward(0.7, 1.0), -0.3);
  EXPECT_EQ(non_positive_reward(1.0, 1.0), 0.0);
  EXPECT_EQ(non_positive_reward(1.2, 1.0), 0.0);
}

}  // namespace
}  // namespace sc
